/**
 * {@code rtaware replay}: the command that loads a recording and runs the {@code rtaware-replay}
 * module's exact or what-if replay of the navigation controller on it, and the run metadata
 * ({@link io.rtaware.app.replay.ControllerMetadata}) that lets it rebuild the recorded
 * controller.
 */
package io.rtaware.app.replay;
