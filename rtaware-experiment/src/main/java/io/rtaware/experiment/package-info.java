/**
 * The paper's experiment: sets of task periods, repeated runs of {@code rtaware run} in fresh
 * JVMs, the results table, Welch t-tests between sets, and the report with its figures.
 */
package io.rtaware.experiment;
