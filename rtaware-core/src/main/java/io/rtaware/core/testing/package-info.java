/**
 * Test fixtures for behavior authors, in main scope so every module's tests can use them:
 * {@link io.rtaware.core.testing.TaskHarness} drives one task or a small graph through the real
 * monitor (real input and output handles, real store, real timing rules) on the step executor,
 * with scripted inputs.
 */
package io.rtaware.core.testing;
