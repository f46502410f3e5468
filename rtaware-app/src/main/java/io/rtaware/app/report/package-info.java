/**
 * The report sections every command adds beside the core report: {@code advice},
 * {@code schedulability} and {@code schedulability_suggested}
 * ({@link io.rtaware.app.report.ReportSections}), shared by
 * {@code bench}, {@code run} and {@code analyze} so they print and write the same thing.
 */
package io.rtaware.app.report;
