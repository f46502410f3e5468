/** {@code rtaware bench}: synthetic task sets with real CPU work, run on the threaded monitor. */
package io.rtaware.app.bench;
