/**
 * Synthetic task sets and competing load for benchmarks ({@code rtaware bench}): a task's
 * period and calibrated CPU work ({@link io.rtaware.bench.load.BenchSpec},
 * {@link io.rtaware.bench.load.BusyWork}), the task itself
 * ({@link io.rtaware.bench.load.BenchTask}), busy threads and garbage at a steady rate
 * ({@link io.rtaware.bench.load.CpuLoad}, {@link io.rtaware.bench.load.GarbageLoad}) and a
 * lateness histogram listener ({@link io.rtaware.bench.load.LatenessHistogram}).
 */
package io.rtaware.bench.load;
