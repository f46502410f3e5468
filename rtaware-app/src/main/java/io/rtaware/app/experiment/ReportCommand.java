package io.rtaware.app.experiment;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFolder;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.ExperimentProfile;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.report.ExperimentReport;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/**
 * {@code rtaware report DIR}: re-renders an experiment's summary.json, report.md, report.html
 * and figures from its results.csv (and the runs' trajectory.csv files).
 */
@Command(name = "report", mixinStandardHelpOptions = true,
        description = {"Re-render an experiment's report (summary.json, report.md, report.html, figures)",
                "from DIR/results.csv and the runs' trajectory.csv files.",
                "Example:", "  rtaware report experiments/paper"})
public final class ReportCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "DIR", description = "An experiment folder (the --out of rtaware experiment).")
    Path dir;

    @Override
    public Integer call() throws IOException {
        OutputFolder.existing("report", dir);
        System.setProperty("java.awt.headless", "true");
        try {
            String scenario = ExperimentProfile.read(dir).map(ExperimentProfile::scenario)
                    .orElseGet(() -> firstScenario(dir));
            ResultsCsv.tornLastLine(dir.resolve(ResultsCsv.FILE_NAME))
                    .ifPresent(note -> System.err.println("rtaware: note: " + note));
            ExperimentReport.render(dir, CourseBackgrounds.forScenario(scenario));
        } catch (ExperimentInputException e) {
            throw new UserError(e.getMessage());
        }
        System.out.println("report written to " + dir.resolve(ExperimentReport.MARKDOWN_FILE) + " and "
                + dir.resolve(ExperimentReport.HTML_FILE));
        return 0;
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
