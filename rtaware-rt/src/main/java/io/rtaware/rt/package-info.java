/**
 * Real-time task threads on Linux: SCHED_FIFO priorities in rate-monotonic order, optional CPU
 * affinity and 1 ns timer slack, set per task thread through JNA
 * ({@link io.rtaware.rt.RealtimeThreads}), with a one-line fallback to normal threads when
 * the process may not use them.
 */
package io.rtaware.rt;
