/**
 * {@code rtaware run}: the options of a robot run of the paper's course, their wiring onto the
 * library's run ({@link io.rtaware.robotrun.NavRun}), the status line and the output folder.
 */
package io.rtaware.app.run;
