/** {@code rtaware run}: the paper's waypoint course, driven by the four behaviors over Player. */
package io.rtaware.app.run;
