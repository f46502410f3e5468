/**
 * The {@code --foxglove [HOST:]PORT} option of {@code run}, {@code bench} and {@code sim}: a
 * Foxglove WebSocket server ({@link io.rtaware.foxglove.FoxgloveServer}) fed by the recorder.
 */
package io.rtaware.app.foxglove;
