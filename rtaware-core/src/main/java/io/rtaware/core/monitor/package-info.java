/**
 * The monitor: releases tasks on their schedules (one platform thread per task, or a step
 * executor on a manual clock for tests), applies the timing rules (absolute release grid,
 * deadline misses reported at the deadline, skipped releases without catch-up bursts, stale
 * runs, expired reads), catches task errors under an explicit policy, and builds the
 * termination report. All timing rules live in one class shared by both executors.
 */
package io.rtaware.core.monitor;
