/**
 * The executor comparison behind {@code rtaware bench --compare} and {@code --sweep-tasks}: the
 * same task set run on rtaware's executors, on {@code ScheduledThreadPoolExecutor}, on a bare
 * parkNanos loop and on the timer wheels of Netty and Agrona, interleaved in segments, with one bookkeeping
 * ({@link io.rtaware.bench.compare.ReleaseStats}) for all. Each executor is a
 * {@link io.rtaware.bench.compare.SegmentExecutor} (one row of the comparison),
 * {@link io.rtaware.bench.compare.CompareRun} runs the rounds and
 * {@link io.rtaware.bench.compare.CompareReport} is the result; usable without the command line.
 */
package io.rtaware.bench.compare;
