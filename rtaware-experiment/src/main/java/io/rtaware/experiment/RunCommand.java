package io.rtaware.experiment;

import java.util.List;

/**
 * How the experiment starts one run: the full command line of a process that does what
 * {@code rtaware run ARGS} does, i.e. exits 0 for any finished run and writes
 * {@code OUT/report.json} and {@code OUT/trajectory.csv}, or exits 2 for a user error.
 * Injectable so that tests can run a stand-in.
 */
@FunctionalInterface
public interface RunCommand {

    /**
     * @param runArguments the arguments after {@code run}, e.g. {@code --scenario paper-room ... --quiet}
     * @return the command line to start
     */
    List<String> commandLine(List<String> runArguments);
}
