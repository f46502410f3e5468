/**
 * {@code rtaware bench}: synthetic task sets (calibrated CPU work), competing load and garbage,
 * run on the monitor to show how a machine copes.
 */
package io.rtaware.app.bench;
