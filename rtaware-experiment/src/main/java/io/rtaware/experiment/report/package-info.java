/**
 * The experiment's report: {@code summary.json}, {@code report.md}, {@code report.html} and
 * the figures (PNG and SVG, drawn with XChart), all rendered from {@code results.csv} and the
 * runs' {@code trajectory.csv} files.
 */
package io.rtaware.experiment.report;
