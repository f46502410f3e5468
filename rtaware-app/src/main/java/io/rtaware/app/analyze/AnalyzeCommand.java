package io.rtaware.app.analyze;

import io.rtaware.app.UserError;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.ReportDocument;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware analyze report.json}: prints the period advice and the schedulability analysis
 * of a saved report, exactly as the run's summary printed them: with the run's machine verdict
 * first, and no advice that blames a task for what the verdict blames on the machine.
 */
@Command(name = "analyze", mixinStandardHelpOptions = true,
        description = {"Print period advice and schedulability for a saved report (rtaware.report/1).",
                "Example:", "  rtaware analyze report.json"})
public final class AnalyzeCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "REPORT", description = "A report.json written by --json.")
    Path file;

    @Option(names = "--cores", paramLabel = "N",
            description = "Core count for the per-core utilization (default: this machine's, ${DEFAULT-VALUE}).")
    int cores = Runtime.getRuntime().availableProcessors();

    @Override
    public Integer call() {
        if (cores < 1) {
            throw new UserError("--cores must be at least 1, got " + cores);
        }
        ReportDocument doc;
        try {
            doc = ReportDocument.read(file);
        } catch (IOException | RuntimeException e) {
            String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage().lines().findFirst().orElse("");
            throw new UserError("cannot read report " + file + ": " + why);
        }
        ReportInput.check(doc.report(), file);
        MachineVerdict machine = ReportSections.machine(doc);
        System.out.println(machine == null ? "machine: not recorded (a report written before rtaware recorded its"
                + " run's conditions): the advice cannot tell the machine's share from the tasks'" : machine.text());
        System.out.print(ReportSections.enrich(doc, cores).text());
        return 0;
    }
}
