/**
 * World time: the {@link io.rtaware.core.time.Clock} injected everywhere, with a system clock,
 * a scaled clock that emulates a slower computer, and a manual clock for exact tests.
 */
package io.rtaware.core.time;
