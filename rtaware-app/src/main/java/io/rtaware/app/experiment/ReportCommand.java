package io.rtaware.app.experiment;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFile;
import io.rtaware.app.output.OutputFolder;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.ExperimentMerge;
import io.rtaware.experiment.FolderCheck;
import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.report.ExperimentReport;
import io.rtaware.experiment.report.ResultsMarkdown;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware report DIR...}: re-renders an experiment's summary.json, report.md, report.html
 * and figures from its results.csv (and the runs' trajectory.csv files); with several folders
 * (the shards of one plan) and {@code --out}, merges them into one folder first.
 */
@Command(name = "report", mixinStandardHelpOptions = true,
        description = {"Re-render an experiment's report (summary.json, report.md, report.html, figures) from "
                + "DIR/results.csv and the runs' trajectory.csv files. With several folders (the shards of one plan, "
                + "made with 'experiment --shard K/N'), merge them into --out first; folders of different plans, or "
                + "holding the same run twice, are refused. With --results FILE, report each folder on its own and "
                + "write FILE (RESULTS.md for the docs).",
                "Examples:", "  rtaware report experiments/paper",
                "  rtaware report shard1 shard2 shard3 --out experiments/sweep"})
public final class ReportCommand implements Callable<Integer> {

    @Parameters(arity = "1..*", paramLabel = "DIR", description = "Experiment folders (the --out of rtaware experiment).")
    List<Path> dirs;

    @Option(names = "--out", paramLabel = "DIR",
            description = "Merge the folders into this new folder and write the report there (needed with several DIRs).")
    Path out;

    @Option(names = "--include-busy", description = "Use every run, not only those made on a quiet machine.")
    boolean includeBusy;

    @Option(names = "--results", paramLabel = "FILE", description = "Report each DIR on its own (no merge) and write "
            + "FILE (for example docs/experiment/RESULTS.md): Tables I and II and the claims beside the paper's, with the "
            + "conditions, for the docs to link.")
    Path results;

    @Override
    public Integer call() {
        if (results != null) {
            return results();
        }
        if (dirs.size() > 1 && out == null) {
            throw new UserError("report: " + dirs.size() + " folders are merged into a new folder: add --out DIR");
        }
        if (out == null) {
            OutputFolder.existing("report", dirs.get(0));
        } else {
            for (Path shard : dirs) {
                if (!Files.isDirectory(shard)) {
                    throw new UserError("report: " + shard + " is not a folder");
                }
            }
            OutputFolder.of("--out", out);
        }
        System.setProperty("java.awt.headless", "true");
        Path dir = out == null ? dirs.get(0) : out;
        String scenario;
        try {
            if (out == null) {
                FolderCheck.rows(dir);
            } else {
                int runs = ExperimentMerge.merge(dirs, out).size();
                System.out.println("merged " + runs + " run(s) from " + dirs.size() + " folder(s) into " + out);
            }
            scenario = ExperimentProfile.read(dir).map(ExperimentProfile::scenario)
                    .orElseGet(() -> firstScenario(dir));
            ResultsCsv.tornLastLine(dir.resolve(ResultsCsv.FILE_NAME))
                    .ifPresent(note -> System.err.println("rtaware: note: " + note));
        } catch (ExperimentInputException e) {
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            System.err.println("rtaware: report: " + (out == null ? "could not read " + dir : "could not merge into " + out)
                    + ": " + e);
            return OutputWrites.EXIT_WRITE_FAILED;
        }
        if (ReportRendering.render(dir, scenario, includeBusy, false, System.err).isEmpty()) {
            return OutputWrites.EXIT_WRITE_FAILED;
        }
        System.out.println("report written to " + dir.resolve(ExperimentReport.MARKDOWN_FILE) + " and "
                + dir.resolve(ExperimentReport.HTML_FILE));
        return 0;
    }

    private int results() {
        if (out != null) {
            throw new UserError("report: --results reports each folder on its own; it does not merge into --out");
        }
        OutputFile.of("--results", results);
        System.setProperty("java.awt.headless", "true");
        List<ResultsMarkdown.Folder> folders = new ArrayList<>();
        for (Path dir : dirs) {
            OutputFolder.existing("report", dir);
            try {
                FolderCheck.rows(dir);
            } catch (ExperimentInputException e) {
                throw new UserError(e.getMessage());
            } catch (IOException e) {
                System.err.println("rtaware: report: could not read " + dir + ": " + e);
                return OutputWrites.EXIT_WRITE_FAILED;
            }
            String scenario = ExperimentProfile.read(dir).map(ExperimentProfile::scenario).orElseGet(() -> firstScenario(dir));
            Optional<ExperimentSummary> summary = ReportRendering.render(dir, scenario, includeBusy, false, System.err);
            if (summary.isEmpty()) {
                return OutputWrites.EXIT_WRITE_FAILED;
            }
            folders.add(new ResultsMarkdown.Folder(dir.toAbsolutePath().normalize().getFileName().toString(),
                    summary.get()));
        }
        StringBuilder command = new StringBuilder("rtaware report --results ").append(results);
        if (includeBusy) {
            command.append(" --include-busy");
        }
        dirs.forEach(d -> command.append(' ').append(d)); // as typed: run it from the checkout with relative paths
        OutputWrites writes = new OutputWrites(System.err);
        if (writes.write(results, () -> ResultsMarkdown.write(results, folders, command.toString()))) {
            System.out.println("results written to " + results + " (" + folders.size() + " experiment(s))");
        }
        return writes.exitStatus(0);
    }

    private static String firstScenario(Path dir) {
        try {
            var rows = ResultsCsv.read(dir.resolve(ResultsCsv.FILE_NAME));
            return rows.isEmpty() ? "" : rows.get(0).conditions().scenario();
        } catch (IOException e) {
            throw new UserError("report: cannot read " + dir.resolve(ResultsCsv.FILE_NAME) + ": " + e.getMessage());
        }
    }
}
