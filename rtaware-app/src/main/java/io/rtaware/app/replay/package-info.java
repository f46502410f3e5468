/**
 * {@code rtaware replay}: the command that loads a recording and runs the {@code rtaware-replay}
 * module's exact or what-if replay of the navigation controller on it, rebuilt from the run
 * metadata the controller recorded ({@link io.rtaware.nav.ControllerMetadata}).
 */
package io.rtaware.app.replay;
