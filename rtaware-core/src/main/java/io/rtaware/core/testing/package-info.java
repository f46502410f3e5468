/**
 * Test fixtures for behavior authors, in main scope so every module's tests can use them:
 * {@link io.rtaware.core.testing.TaskHarness} drives one task or a small graph through the real
 * monitor (real input and output handles, real store, real timing rules) on the step executor,
 * with scripted inputs; {@link io.rtaware.core.testing.ThreadAllocation} counts the bytes a set of
 * threads allocated over a steady state (steady-state task cycles allocate nothing), and
 * {@link io.rtaware.core.testing.LiveThreads} finds the live threads without stopping them.
 */
package io.rtaware.core.testing;
