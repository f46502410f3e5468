package io.rtaware.app.analyze;

import io.rtaware.app.UserError;
import io.rtaware.app.replay.ReplayCommand;
import io.rtaware.bench.load.BenchRecording;
import io.rtaware.core.analysis.AnalysisText;
import io.rtaware.core.analysis.PeriodAdvisor;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.analysis.Schedulability;
import io.rtaware.core.report.ReportChecks;
import io.rtaware.nav.ControllerMetadata;
import io.rtaware.core.conditions.MachineVerdict;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.record.mcap.McapFormatException;
import io.rtaware.replay.AdviceCheck;
import io.rtaware.replay.Recording;
import io.rtaware.replay.ReplayProviders;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware analyze report.json}: prints the period advice and the schedulability analysis
 * of a saved report, exactly as the run's summary printed them: with the run's machine verdict
 * first, and no longer period that rests on execution times the machine inflated. With
 * {@code --verify FILE.mcap}, the advice is checked by what-if replays of the recording
 * ({@link AdviceCheck}): before and after side by side, and a change the replays show to be
 * worse withdrawn with its figures. Without a report, the advice is made from the replay of the
 * recording with its recorded periods.
 */
@Command(name = "analyze", mixinStandardHelpOptions = true,
        description = {"Print period advice and schedulability for a saved report (rtaware.report/1), and check the"
                + " advice by replaying a recording with it.",
                "Examples:", "  rtaware analyze report.json",
                "  rtaware analyze runs/x/report.json --verify run.mcap",
                "  rtaware analyze --verify run.mcap"})
public final class AnalyzeCommand implements Callable<Integer> {

    @Parameters(index = "0", arity = "0..1", paramLabel = "REPORT",
            description = "A report.json written by run, bench --json or replay --out.")
    Path file;

    @Option(names = "--cores", paramLabel = "N",
            description = "Cores the tasks may use, for the response-time analysis (default: this machine's, or the"
                    + " recording machine's when only a recording is given).")
    Integer cores;

    @Option(names = "--verify", paramLabel = "FILE.mcap",
            description = "A recording of 'run --record' or 'bench --record' of the same task set: replay it with the"
                    + " recorded periods and with the suggested ones, print misses and stale runs before and after"
                    + " side by side, and withdraw a change the replay shows to be worse.")
    Path verify;

    @Override
    public Integer call() {
        if (cores != null && cores < 1) {
            throw new UserError("--cores must be at least 1, got " + cores);
        }
        if (file == null && verify == null) {
            throw new UserError("give a report.json, a recording (--verify FILE.mcap), or both");
        }
        PrintStream out = System.out;
        ReportDocument doc = file == null ? null : read(file);
        if (verify == null) {
            MachineVerdict machine = ReportSections.machine(doc);
            out.println(machine == null ? "machine: not recorded (a report written before rtaware recorded its"
                    + " run's conditions): the advice cannot tell the machine's share from the tasks'" : machine.text());
            out.print(ReportSections.enrich(doc, cores != null ? cores : Runtime.getRuntime().availableProcessors())
                    .text());
            return 0;
        }
        Recording recording = ReplayCommand.load(verify);
        if (recording.tasks().isEmpty()) {
            throw new UserError(verify + " has no /rtaware/timing channels: not a recording of 'rtaware run --record'"
                    + " or 'rtaware bench --record'");
        }
        Set<String> settable;
        AdviceCheck.Controller controller;
        if (BenchRecording.is(recording)) {
            try {
                controller = BenchRecording.controller(recording, verify);
            } catch (IllegalArgumentException e) {
                throw new UserError(e.getMessage());
            }
            settable = recording.tasks().keySet();
        } else {
            // Any controller with a replay provider on the class path (the paper's nav controller is one).
            ReplayProviders.RecordedController recorded;
            Map<String, Long> recordedNs;
            try {
                recorded = ReplayProviders.load(AnalyzeCommand.class.getClassLoader())
                        .controllerOf(recording.runMetadata());
                recordedNs = recorded.recordedPeriodsNs();
            } catch (IllegalArgumentException e) {
                throw new UserError(verify + ": " + e.getMessage());
            }
            controller = periods -> {
                Map<String, Long> all = new LinkedHashMap<>(recordedNs); // every period pinned (the mediator's too)
                all.putAll(periods);
                return recorded.tasks(all);
            };
            settable = recordedNs.keySet();
        }
        try {
            return verify(out, doc, recording, controller, settable);
        } catch (McapFormatException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            throw new UserError(verify + ": " + e.getMessage());
        }
    }

    private int verify(PrintStream out, ReportDocument doc, Recording recording, AdviceCheck.Controller controller,
                       Set<String> settable) throws IOException {
        Report before = AdviceCheck.replay(recording, controller, Map.of());
        int n = cores != null ? cores : doc != null ? Runtime.getRuntime().availableProcessors() : recordedCores(recording);
        MachineVerdict machine = null;
        Report run = before;
        if (doc != null) {
            machine = ReportSections.machine(doc);
            out.println(machine == null ? "machine: not recorded in " + file : machine.text());
            run = doc.report();
        } else {
            out.println("machine: not applied: the advice is made from a replay of " + verify + " with its recorded"
                    + " periods, and every replay below charges the same recorded execution times");
        }
        Report advised = run;
        MachineVerdict judged = machine;
        AdviceCheck.Result check = AdviceCheck.verify(recording, controller, settable, before,
                withdrawn -> PeriodAdvisor.advise(advised, n, judged, withdrawn));
        out.println();
        out.print(AdviceCheck.text(check, verify.toString()));
        out.println();
        out.print(AnalysisText.advice(check.advice()));
        out.println();
        out.print(AnalysisText.schedulability(Schedulability.analyze(run, n)));
        return 0;
    }

    /** @return the recording machine's core count from its metadata, else this machine's */
    private static int recordedCores(Recording recording) {
        try {
            return Math.max(1, Integer.parseInt(recording.runMetadata().getOrDefault(ControllerMetadata.CORES, "")));
        } catch (NumberFormatException e) {
            return Runtime.getRuntime().availableProcessors();
        }
    }

    private static ReportDocument read(Path file) {
        ReportDocument doc;
        try {
            doc = ReportDocument.read(file);
        } catch (IOException | RuntimeException e) {
            String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage().lines().findFirst().orElse("");
            throw new UserError(why.startsWith(file.toString()) ? "report " + why : "cannot read report " + file + ": " + why);
        }
        try {
            ReportChecks.check(doc.report(), file);
        } catch (IllegalArgumentException e) {
            throw new UserError(e.getMessage());
        }
        return doc;
    }
}
