/** A tiny simulated room for the nav tests (the tasks run on the core's {@code TaskHarness}). */
package io.rtaware.nav.testing;
