/**
 * The monitor: releases tasks on their schedules (one platform thread per task, or a step
 * executor on a manual clock for tests), applies the timing rules (absolute release grid,
 * deadline misses reported at the deadline, skipped releases without catch-up bursts, stale
 * runs, expired reads), catches task errors under an explicit policy, and builds the
 * termination report. All timing rules live in one class, the rulebook
 * {@link io.rtaware.core.monitor.TaskRuntime}, shared by every executor; executors only wait and
 * call (see {@link io.rtaware.core.monitor.Executor}). Faults of listeners, handlers and executors
 * are contained and reported to one {@link io.rtaware.core.monitor.FrameworkErrorHandler}.
 * {@code docs/ARCHITECTURE.md} maps the classes.
 */
package io.rtaware.core.monitor;
