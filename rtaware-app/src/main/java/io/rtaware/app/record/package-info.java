/** Commands over recordings: {@code rtaware inspect}. */
package io.rtaware.app.record;
