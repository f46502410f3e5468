/**
 * Output files written so that nothing at their path is destroyed:
 * {@link io.rtaware.core.output.OutputFiles} writes a regular file whole or not at all (a
 * temporary name beside it, renamed once complete), writes into a pipe or a character device
 * in place, and refuses what no file can replace (a folder, a socket, a block device). Every
 * file and image rtaware writes goes through it. {@link io.rtaware.core.output.Palette} is the one
 * set of colours every figure gives its series, and {@link io.rtaware.core.output.FigureText}
 * shrinks a title until it fits the figure as painted.
 */
package io.rtaware.core.output;
