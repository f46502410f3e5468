package io.rtaware.app.experiment;

import io.rtaware.app.UserError;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.experiment.ExperimentInputException;
import io.rtaware.experiment.ExperimentSummary;
import io.rtaware.experiment.ResultsCsv;
import io.rtaware.experiment.report.CourseBackgrounds;
import io.rtaware.experiment.report.ExperimentReport;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Renders an experiment folder's report for the commands that write one ({@code experiment},
 * {@code report}). A folder that cannot be reported (no runs, no quiet run, a malformed file) is
 * the user's one-line error. Any other failure (a write that fails, or a bug in the summary, the
 * claims or the figures) is one line naming the folder, the cause and where it was thrown, and
 * saying that the runs are safe in {@code results.csv}: the command then ends with
 * {@link OutputWrites#EXIT_WRITE_FAILED}. Stateless.
 */
final class ReportRendering {

    private ReportRendering() {
    }

    /**
     * @param dir an experiment folder
     * @param scenario its course, for the background of the paths
     * @param includeBusy true to use every run, not only the quiet ones
     * @param allWhenNoneQuiet true to use every run, labelled busy, when none was quiet ({@code --allow-busy})
     * @param err where the line of a failure goes
     * @return the summary written, or empty when the report could not be written (the line is printed)
     * @throws UserError if the folder cannot be reported
     */
    static Optional<ExperimentSummary> render(Path dir, String scenario, boolean includeBusy, boolean allWhenNoneQuiet,
                                              PrintStream err) {
        try {
            return Optional.of(ExperimentReport.render(dir, CourseBackgrounds.forScenario(scenario), includeBusy,
                    allWhenNoneQuiet));
        } catch (ExperimentInputException e) {
            throw new UserError(e.getMessage());
        } catch (IOException | UncheckedIOException e) {
            return failed(dir, e.getMessage(), err);
        } catch (RuntimeException e) { // a bug: the line says where, so that it can be reported
            StackTraceElement at = e.getStackTrace().length == 0 ? null : e.getStackTrace()[0];
            return failed(dir, e + (at == null ? "" : " (at " + at.getClassName() + "." + at.getMethodName() + ":"
                    + at.getLineNumber() + ")"), err);
        }
    }

    private static Optional<ExperimentSummary> failed(Path dir, String cause, PrintStream err) {
        String oneLine = String.valueOf(cause).lines().findFirst().orElse("");
        err.println("rtaware: could not write the report of " + dir + ": " + oneLine + "; the runs are kept in "
                + dir.resolve(ResultsCsv.FILE_NAME) + " (rtaware report " + dir + " writes the report again)");
        err.flush();
        return Optional.empty();
    }
}
