/**
 * Where a command writes: every output path named on the command line ({@code run --out},
 * {@code bench --json}, {@code --trace}, {@code experiment --out}, {@code report DIR}) is checked
 * once, before anything runs ({@link io.rtaware.app.output.OutputFile},
 * {@link io.rtaware.app.output.OutputFolder}); the writes themselves go through
 * {@link io.rtaware.core.output.OutputWrites}, which writes what it can, names every file that
 * failed with the reason, and makes the command's exit status non-zero.
 */
package io.rtaware.app.output;
