/**
 * The termination summary: the {@link io.rtaware.core.report.Report} (schema
 * {@code rtaware.report/1}) a program reads, with sections added by later layers
 * ({@link io.rtaware.core.report.ReportDocument}), and the table a person reads
 * ({@link io.rtaware.core.report.SummaryTable}).
 */
package io.rtaware.core.report;
