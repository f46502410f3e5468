package io.rtaware.app.run;

import io.rtaware.experiment.ExperimentRunner;
import java.io.PrintStream;
import java.util.Optional;
import java.util.function.IntConsumer;

/**
 * Ends a run whose experiment is gone: a run started by {@code rtaware experiment} learns the
 * experiment's pid from {@link ExperimentRunner#PARENT_PID_ENV}, and when that process ends (a
 * SIGKILL included, which the experiment itself cannot pass on) the run says so in one line and
 * exits with status {@value #EXIT_PARENT_GONE}, whose shutdown hook stops the robot and writes the
 * report, instead of going on writing into a folder that a resumed experiment fills again.
 */
final class ExperimentParentWatch {

    /** Exit status of a run whose experiment is gone: 128 + SIGHUP, the signal a lost terminal sends. */
    static final int EXIT_PARENT_GONE = 129;

    private ExperimentParentWatch() {
    }

    /**
     * @param pidText the variable's value, or null outside an experiment
     * @param err where the line goes
     * @param exit what exits the process ({@code System::exit} in the product)
     * @return true if a watch was started (or the experiment was gone already, and {@code exit} ran)
     */
    static boolean start(String pidText, PrintStream err, IntConsumer exit) {
        if (pidText == null || pidText.isBlank()) {
            return false;
        }
        long pid;
        try {
            pid = Long.parseLong(pidText.strip());
        } catch (NumberFormatException e) {
            err.println("rtaware run: warning: " + ExperimentRunner.PARENT_PID_ENV + "='" + pidText
                    + "' is not a pid; not watching the experiment");
            return false;
        }
        Optional<ProcessHandle> parent = ProcessHandle.of(pid).filter(ProcessHandle::isAlive);
        if (parent.isEmpty()) {
            gone(pid, err, exit);
            return true;
        }
        parent.get().onExit().thenRun(() -> gone(pid, err, exit));
        return true;
    }

    private static void gone(long pid, PrintStream err, IntConsumer exit) {
        err.println("rtaware run: the experiment that started this run (pid " + pid + ") is gone; stopping the robot");
        err.flush();
        exit.accept(EXIT_PARENT_GONE);
    }
}
