/**
 * What to change, derived from a finished run: period advice from the tasks' data dependencies,
 * stale runs and execution times ({@link io.rtaware.core.analysis.PeriodAdvisor}), and a
 * schedulability analysis under rate-monotonic priorities
 * ({@link io.rtaware.core.analysis.Schedulability}). Everything here is a pure function of a
 * {@link io.rtaware.core.report.Report} (plus the machine's core count), so a saved
 * {@code report.json} gives the same answer as the live run.
 * {@link io.rtaware.core.analysis.ReportSections} adds both to a report document ({@code advice},
 * {@code schedulability}, and an adaptive run's {@code period_history}), as every command of
 * {@code rtaware} that prints or writes a report does.
 */
package io.rtaware.core.analysis;
