/** Commands that talk to a Player robot server directly. */
package io.rtaware.app.player;
