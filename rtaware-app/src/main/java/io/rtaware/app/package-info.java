/** The {@code rtaware} command line: the composition root that wires every program. */
package io.rtaware.app;
