package io.rtaware.app.run;

import io.rtaware.app.cli.TraceOptions;
import io.rtaware.live.LiveOptions;
import java.nio.file.Path;

/**
 * Everything {@code rtaware run} was asked to do, validated.
 *
 * @param scenario {@code paper-room} or a scenario file
 * @param periods the four behaviors' periods
 * @param timeScale world seconds per wall second
 * @param playerHost external Player server host, or null for the built-in simulator
 * @param playerPort external Player server port
 * @param seed the simulator's seed
 * @param outDir where the report goes
 * @param quiet no live status or miss lines
 * @param stuckAfterS world seconds without progress after which the robot counts as stuck
 * @param gridResolutionM occupancy grid resolution
 * @param modelName the robot's model name for {@code simulation:0} ground truth
 * @param trace the {@code --trace} options
 * @param realtime SCHED_FIFO task threads in rate-monotonic order, when permitted
 * @param kernelTimerSlack leave the task threads the kernel's timer slack instead of asking for 1 ns
 * @param live whether and where to serve the live view
 * @param robot {@code koala}, {@code ideal}, or null for the scenario's model (default koala)
 * @param topSpeedMps the controller's top speed in m/s, or null for the scenario's (default 0.1)
 * @param inflationMarginM clearance the planner adds to the robot's radius, metres
 * @param robotSeed seed of the simulated robot's systematic odometry errors: one robot per seed
 */
public record RunOptions(String scenario, TaskPeriods periods, double timeScale, String playerHost, int playerPort,
                         long seed, Path outDir, boolean quiet, double stuckAfterS, double gridResolutionM,
                         String modelName, TraceOptions trace, boolean realtime, boolean kernelTimerSlack, LiveOptions live,
                         String robot, Double topSpeedMps, double inflationMarginM, long robotSeed) {

    /** @return true when the robot is the built-in simulator */
    public boolean builtInSimulator() {
        return playerHost == null;
    }
}
