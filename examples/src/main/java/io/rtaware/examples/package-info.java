/**
 * Runnable examples of rtaware used as a library, without its command line:
 * {@link io.rtaware.examples.ThreeTaskController} embeds the monitor with real-time threads,
 * records the run to MCAP and replays the recording.
 */
package io.rtaware.examples;
