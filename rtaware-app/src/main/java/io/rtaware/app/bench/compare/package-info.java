/**
 * {@code rtaware bench --compare}: the same task set run on rtaware's threaded executor, on
 * {@code ScheduledThreadPoolExecutor} and on a bare parkNanos loop, interleaved in segments, with
 * one bookkeeping ({@link io.rtaware.app.bench.compare.ReleaseStats}) for all three.
 */
package io.rtaware.app.bench.compare;
