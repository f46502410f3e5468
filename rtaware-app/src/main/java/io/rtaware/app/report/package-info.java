/**
 * The report sections every command adds beside the core report: {@code advice} and
 * {@code schedulability} ({@link io.rtaware.app.report.ReportSections}), shared by
 * {@code bench}, {@code run} and {@code analyze} so they print and write the same thing.
 */
package io.rtaware.app.report;
