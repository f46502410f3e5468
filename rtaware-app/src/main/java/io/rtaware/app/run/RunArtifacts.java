package io.rtaware.app.run;

import io.rtaware.app.report.ReportSections;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.core.report.SummaryTable;
import io.rtaware.nav.NavConfig;
import io.rtaware.nav.map.PgmMapWriter;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.render.WorldRenderer;
import io.rtaware.sim.scenario.Scenario;
import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Writes a run's output folder: {@code report.json} (core report plus the {@code run} section),
 * {@code report.md}, {@code trajectory.csv}, {@code trajectory.png}, and the grid the robot built
 * as {@code map.pgm} + {@code map.yaml}. Prints the termination summary first, so a person sees
 * it even if a file cannot be written. Called once, from the monitor's termination handler.
 */
final class RunArtifacts {

    private final RunOptions options;
    private final Scenario scenario;
    private final NavConfig navConfig;
    private final PrintStream out;
    private final Map<String, Object> sections = new LinkedHashMap<>();

    RunArtifacts(RunOptions options, Scenario scenario, NavConfig navConfig, PrintStream out) {
        this.options = options;
        this.scenario = scenario;
        this.navConfig = navConfig;
        this.out = out;
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

    void write(Report report, RunSection run, Referee referee, OccupancyGrid builtMap, OccupancyMap worldMap) {
        String table = SummaryTable.format(report);
        String runText = runText(run);
        ReportDocument doc = new ReportDocument(report).section("run", run);
        sections.forEach(doc::section);
        String analysis = ReportSections.enrich(doc, Runtime.getRuntime().availableProcessors()).text();
        out.println();
        out.print(table);
        out.println();
        out.print(runText);
        out.println();
        out.print(analysis);
        Path dir = options.outDir();
        try {
            Files.createDirectories(dir);
            doc.write(dir.resolve("report.json"));
            Files.writeString(dir.resolve("report.md"), markdown(table, runText, analysis, worldMap != null));
            List<Referee.Sample> samples = referee == null ? List.of() : referee.samples();
            writeTrajectoryCsv(dir.resolve("trajectory.csv"), samples);
            if (worldMap != null) {
                List<Pose2d> poses = samples.stream().map(Referee.Sample::pose).toList();
                new WorldRenderer().writePng(scenario, worldMap, poses,
                        referee == null ? List.of() : referee.missMarkers(), dir.resolve("trajectory.png"));
            }
            if (builtMap != null) {
                PgmMapWriter.write(builtMap, dir, "map");
            }
            out.println("report written to " + dir + " (report.json, report.md, trajectory.csv"
                    + (worldMap != null ? ", trajectory.png" : "") + (builtMap != null ? ", map.pgm, map.yaml" : "") + ")");
        } catch (IOException | UncheckedIOException e) {
            System.err.println("rtaware: could not write the run's report to " + dir + ": " + e.getMessage());
        }
    }

    private String runText(RunSection r) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "run: %s (%s) after %.1f s of world time; waypoints %d of %d%n",
                r.outcome(), r.reason(), r.runTimeS(), r.waypointsReached(), r.waypointsTotal()));
        sb.append(String.format(Locale.ROOT, "     distance to finish %.2f m, travelled %.2f m, collisions %d (measured on %s)%n",
                r.distanceToFinishM(), r.distanceTravelledM(), r.collisions(), r.measuredOn().replace('_', ' ')));
        sb.append(String.format(Locale.ROOT, "     mediator: obstacle won %d cycles, waypoint %d, stop %d (%d because a request was too old)%n",
                r.mediator().get("obstacle"), r.mediator().get("waypoint"), r.mediator().get("stop"), r.staleStops()));
        sb.append(String.format(Locale.ROOT, "     scenario %s, periods %s, time scale x%s, seed %d, grid %.2f m%n",
                r.scenario(), options.periods(), r.timeScale(), r.seed(), navConfig.gridResolutionM()));
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

    private static void writeTrajectoryCsv(Path file, List<Referee.Sample> samples) throws IOException {
        StringBuilder sb = new StringBuilder("t_s,x_m,y_m,yaw_rad\n");
        for (Referee.Sample s : samples) {
            sb.append(String.format(Locale.ROOT, "%.3f,%.4f,%.4f,%.4f%n", s.tS(), s.pose().xM(), s.pose().yM(),
                    s.pose().yawRad()));
        }
        Files.writeString(file, sb);
    }
}
