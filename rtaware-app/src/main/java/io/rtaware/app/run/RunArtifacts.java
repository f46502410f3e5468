package io.rtaware.app.run;

import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.analysis.ReportSections;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.output.OutputFiles;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.map.PgmMapWriter;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robotrun.GroundTruthGap;
import io.rtaware.robotrun.PlayerSection;
import io.rtaware.robotrun.Referee;
import io.rtaware.robotrun.RunSection;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.render.WorldRenderer;
import io.rtaware.sim.scenario.Scenario;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes a run's output folder: {@code report.json} (core report plus the {@code run},
 * {@code player} and {@code conditions} sections; the machine's verdict is the last line of the
 * run's summary),
 * {@code report.md}, {@code trajectory.csv}, {@code trajectory.png}, and the grid the robot built
 * as {@code map.pgm} + {@code map.yaml}. Prints the termination summary first, so a person sees
 * it even if a file cannot be written. Each file is written on its own: one that fails is named
 * with the reason and the others are still written ({@link OutputWrites}); the command's exit
 * status then says so ({@link #exitStatus(int)}). Called once, from the monitor's termination
 * handler.
 */
final class RunArtifacts {

    private final RunOptions options;
    private final Scenario scenario;
    private final NavConfig navConfig;
    private final PrintStream out;
    private final OutputWrites writes;
    private final Map<String, Object> sections = new LinkedHashMap<>();

    RunArtifacts(RunOptions options, Scenario scenario, NavConfig navConfig, PrintStream out, PrintStream err) {
        this.options = options;
        this.scenario = scenario;
        this.navConfig = navConfig;
        this.out = out;
        this.writes = new OutputWrites(err);
    }

    /** @return the run's writes, for other outputs of the same run (the trace) */
    OutputWrites writes() {
        return writes;
    }

    /**
     * @param status the run's exit status from its outcome
     * @return that status, or non-zero if an output could not be written
     */
    int exitStatus(int status) {
        return writes.exitStatus(status);
    }

    /**
     * Adds a section to {@code report.json} (null values are left out).
     *
     * @param name the section's key
     * @param value its content
     */
    void section(String name, Object value) {
        if (value != null) {
            sections.put(name, value);
        }
    }

    /** The period advice and schedulability; a bug in them must not cost the report, written without. */
    private String analysisText(ReportDocument doc) {
        try {
            return ReportSections.enrich(doc, Runtime.getRuntime().availableProcessors()).text();
        } catch (RuntimeException e) {
            writes.failed("analyze the run (period advice, schedulability)", e);
            return "analysis: not available (" + e + ")\n";
        }
    }

    /**
     * @param player the {@code player} section, or null when the robot was not a Player server
     */
    void write(Report report, RunSection run, PlayerSection player, Referee referee, OccupancyGrid builtMap,
               OccupancyMap worldMap) {
        String table = SummaryTable.format(report);
        String runText = runText(run, player);
        ReportDocument doc = new ReportDocument(report).section("run", run);
        if (player != null) {
            doc.section("player", player);
        }
        sections.forEach(doc::section);
        String analysis = analysisText(doc);
        out.println();
        out.print(table);
        out.println();
        out.print(runText);
        out.println();
        out.print(analysis);
        Path dir = options.outDir();
        if (!writes.write(dir, () -> Files.createDirectories(dir))) {
            return;
        }
        List<String> names = new ArrayList<>();
        if (writes.writeFile(dir.resolve("report.json"), doc::write)) {
            names.add("report.json");
        }
        if (writes.writeFile(dir.resolve("report.md"), OutputFiles.text(markdown(table, runText, analysis,
                worldMap != null)))) {
            names.add("report.md");
        }
        List<Referee.Sample> samples = referee == null ? List.of() : referee.samples();
        if (writes.writeFile(dir.resolve("trajectory.csv"), OutputFiles.text(trajectoryCsv(samples)))) {
            names.add("trajectory.csv");
        }
        if (worldMap != null) {
            List<Pose2d> poses = samples.stream().map(Referee.Sample::pose).toList();
            // The believed path only beside a measured true one (with odometry as the referee's source they are the same).
            List<Pose2d> believed = referee == null || !"ground_truth".equals(referee.kind()) ? List.of()
                    : samples.stream().map(Referee.Sample::believed).filter(java.util.Objects::nonNull).toList();
            String ending = run.outcome() + ": " + run.reason();
            if (writes.writeFile(dir.resolve("trajectory.png"), OutputFiles.png(new WorldRenderer().render(scenario,
                    worldMap, poses, believed, referee == null ? List.of() : referee.missMarkers(), ending)))) {
                names.add("trajectory.png");
            }
        }
        // The YAML names the image: written only beside a whole one.
        if (builtMap != null && writes.writeFile(dir.resolve("map.pgm"), PgmMapWriter.pgm(builtMap))) {
            names.add("map.pgm");
            if (writes.writeFile(dir.resolve("map.yaml"), OutputFiles.text(PgmMapWriter.yaml(builtMap, "map.pgm")))) {
                names.add("map.yaml");
            }
        }
        if (!names.isEmpty()) {
            out.println("report written to " + dir + " (" + String.join(", ", names) + ")");
        }
    }

    private String runText(RunSection r, PlayerSection player) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "run: %s (%s) after %.1f s of world time; waypoints %d of %d%n",
                r.outcome(), r.reason(), r.runTimeS(), r.waypointsReached(), r.waypointsTotal()));
        sb.append(String.format(Locale.ROOT, "     distance to finish %s, travelled %.2f m, collisions %d (measured on %s)%n",
                r.distanceToFinishM() == null ? "unknown (no ground truth at the end)"
                        : String.format(Locale.ROOT, "%.2f m", r.distanceToFinishM()),
                r.distanceTravelledM(), r.collisions(), r.measuredOn().replace('_', ' ')));
        if (r.minClearanceM() != null) {
            sb.append(String.format(Locale.ROOT, "     nearest approach %s%.3f m to an obstacle, %d near miss(es) (within %.2f m without touching)%n",
                    r.minClearanceM() >= r.clearanceLimitM() ? "at least " : "", r.minClearanceM(), r.nearMisses(),
                    r.nearMissMarginM()));
        }
        if (!r.groundTruthGaps().isEmpty()) {
            StringBuilder spans = new StringBuilder();
            for (GroundTruthGap g : r.groundTruthGaps()) {
                spans.append(spans.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.1f-%.1f s%s",
                        g.fromS(), g.toS(), g.open() ? " (to the end)" : ""));
            }
            sb.append(String.format(Locale.ROOT, "     ground truth lost: %s; distance travelled measured over %.1f s of"
                    + " %.1f s%n", spans, r.groundTruthCoveredS(), r.runTimeS()));
        }
        StringBuilder rejected = new StringBuilder();
        if (player != null) {
            player.devices().forEach((device, samples) -> {
                if (samples.rejectedSamples() > 0) {
                    rejected.append(rejected.length() == 0 ? "" : ", ").append(device).append(' ')
                            .append(samples.rejectedSamples()).append(" of ").append(samples.samples());
                }
            });
        }
        if (rejected.length() > 0) {
            sb.append("     impossible samples rejected: ").append(rejected).append(System.lineSeparator());
        }
        sb.append(String.format(Locale.ROOT, "     mediator: obstacle won %d cycles, waypoint %d, stop %d (%d because a request was too old)%n",
                r.mediator().get("obstacle"), r.mediator().get("waypoint"), r.mediator().get("stop"), r.staleStops()));
        for (RunSection.WaypointPass p : r.waypointPasses()) {
            sb.append(String.format(Locale.ROOT, "     waypoint %d believed passed at %.1f s: %s%.2f m by odometry%s%n",
                    p.index() + 1, p.tS(), p.trueDistanceM() == null ? ""
                            : String.format(Locale.ROOT, "%.2f m from it in truth (", p.trueDistanceM()),
                    p.believedDistanceM(), p.trueDistanceM() == null ? "" : ")"));
        }
        sb.append(String.format(Locale.ROOT, "     scenario %s, periods %s, time scale x%s, seed %d, grid %.2f m, robot %s at %s m/s%s%n",
                r.scenario(), options.periods(), r.timeScale(), r.seed(), navConfig.grid().resolutionM(),
                r.robotModel().get("name"), r.robotModel().get("top_speed_mps"),
                r.robotSeed() == null ? "" : ", robot seed " + r.robotSeed()));
        if (sections.get(Conditions.SECTION) instanceof Conditions c) {
            sb.append("     ").append(c.summaryLine()).append(System.lineSeparator());
        }
        return sb.toString();
    }

    private String markdown(String table, String runText, String analysis, boolean withTrajectoryPng) {
        return "# rtaware run: " + scenario.name() + "\n\n"
                + "```\n" + runText + "```\n\n"
                + "## Timing\n\n```\n" + table + "```\n\n"
                + "## Period advice and schedulability\n\n```\n" + analysis + "```\n\n"
                + "Definitions: a release is a grid point at which a task was due; a miss is a release whose run did not\n"
                + "finish by its deadline, plus every release skipped because the task was still running; a stale run\n"
                + "is a cycle in which none of the task's inputs had new data. Times are world time.\n\n"
                + (withTrajectoryPng ? "![trajectory](trajectory.png)\n" : "");
    }

    private static String trajectoryCsv(List<Referee.Sample> samples) {
        StringBuilder sb = new StringBuilder("t_s,x_m,y_m,yaw_rad,odom_x_m,odom_y_m,odom_yaw_rad\n");
        for (Referee.Sample s : samples) {
            sb.append(String.format(Locale.ROOT, "%.3f,%.4f,%.4f,%.4f", s.tS(), s.pose().xM(), s.pose().yM(),
                    s.pose().yawRad()));
            Pose2d b = s.believed();
            sb.append(b == null ? ",,," : String.format(Locale.ROOT, ",%.4f,%.4f,%.4f", b.xM(), b.yM(), b.yawRad()));
            sb.append('\n');
        }
        return sb.toString();
    }
}
