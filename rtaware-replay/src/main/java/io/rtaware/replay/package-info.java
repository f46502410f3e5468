/**
 * {@code rtaware replay}: a recording ({@code run --record}) re-executed offline. Exact replay
 * ({@link io.rtaware.replay.ExactReplay}) feeds each task of the controller the input values
 * it read in every recorded cycle and compares what it commits with what it committed; what-if
 * replay ({@link io.rtaware.replay.WhatIfReplay}) runs the controller on the recorded sensor
 * stream with other periods, charging each cycle a recorded execution time. The recording is
 * loaded by {@link io.rtaware.replay.Recording}.
 */
package io.rtaware.replay;
