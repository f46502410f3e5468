package io.rtaware.experiment;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.OptionalLong;

/**
 * What {@code report} checks of an experiment folder before it reads a number from it: no running
 * experiment is writing into it, its {@code results.csv} holds no impossible value
 * ({@link ResultsCsv#readRows}), and every row is a run of the folder's own plan: a set and run
 * within it, with the periods and top speed the plan gives that set, and of the folder's shard. A folder that fails is refused with one line naming the
 * file and the line. Stateless.
 */
public final class FolderCheck {

    private FolderCheck() {
    }

    /**
     * @param dir an experiment folder
     * @return its rows, checked
     * @throws IOException if a file cannot be read
     * @throws ExperimentInputException naming the first problem
     */
    public static List<ResultsCsv.Row> rows(Path dir) throws IOException {
        OptionalLong writer = FolderLock.inUse(dir);
        if (writer.isPresent()) {
            throw new ExperimentInputException(dir + " is being written by a running rtaware experiment"
                    + (writer.getAsLong() > 0 ? " (pid " + writer.getAsLong() + ")" : "")
                    + "; wait for it to end before reporting it");
        }
        Path csv = dir.resolve(ResultsCsv.FILE_NAME);
        if (!Files.exists(csv)) {
            throw new ExperimentInputException(dir + " has no " + ResultsCsv.FILE_NAME + " (not an experiment folder?)");
        }
        List<ResultsCsv.Row> rows = ResultsCsv.readRows(csv);
        Optional<ExperimentPlan> plan = PlanFile.read(dir);
        if (plan.isPresent()) {
            ExperimentPlan p = plan.get();
            for (ResultsCsv.Row row : rows) {
                int set = row.result().set();
                int run = row.result().run();
                if (set > p.sets().size() || run > p.runsPerSet()) {
                    throw new ExperimentInputException(csv + " line " + row.line() + ": set " + set + " run " + run
                            + " is outside the plan of " + dir + " (" + p.sets().size() + " sets x " + p.runsPerSet()
                            + " runs)");
                }
                PeriodSet planned = p.sets().get(set - 1);
                PeriodSet given = row.result().periods();
                if (!(planned.name().equals(given.name()) && planned.sameRunsAs(given))) {
                    throw new ExperimentInputException(csv + " line " + row.line() + ": set " + set + " run " + run
                            + " is '" + given.name() + "' (" + given.label() + ") but set " + set + " of the plan of " + dir
                            + " is '" + planned.name() + "' (" + planned.label() + ")");
                }
                if (!p.shard().includes(set, run)) {
                    throw new ExperimentInputException(csv + " line " + row.line() + ": set " + set + " run " + run
                            + " is not a run of shard " + p.shard() + ", the shard of " + dir);
                }
            }
        }
        return rows;
    }
}
