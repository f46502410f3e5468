/**
 * Text for people: the nearest known name to a mistyped one, for messages that suggest it.
 */
package io.rtaware.core.text;
