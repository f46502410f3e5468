/**
 * The {@code experiment} and {@code report} commands: the paper's experiment (Tables I and II,
 * Figures 7 and 8) on any sets of periods, and re-rendering its report from results.csv.
 */
package io.rtaware.app.experiment;
