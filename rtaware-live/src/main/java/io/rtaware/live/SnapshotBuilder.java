package io.rtaware.live;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.rtaware.core.data.FeedStats;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.TaskCounters;
import io.rtaware.core.monitor.TaskInfo;
import io.rtaware.core.report.Rounding;
import io.rtaware.core.task.Schedule;
import io.rtaware.nav.task.PositionMediatorTask;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.RobotKeys;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;

/**
 * Builds the live snapshots (schema {@value #SCHEMA}) from a monitor's live counters, feed
 * statistics and key values, keeping the short history the "last few seconds" figures need and
 * the robot's trail. Confined to the publisher thread: not thread-safe.
 */
final class SnapshotBuilder {

    /** Schema identifier in every snapshot. */
    static final String SCHEMA = "rtaware.live/1";
    /** World time the "recent" figures look back over, at least. */
    static final long RECENT_WORLD_NS = 5_000_000_000L;
    /** Wall time the "recent" figures look back over, at least (three snapshots, so fast time scales are not noisy). */
    static final long RECENT_WALL_NS = 600_000_000L;
    private static final int MAX_TRAIL_POINTS = 4000;
    private static final double TRAIL_STEP_M = 0.02;
    private static final int LASER_STRIDE = 4;

    /** Counters at one snapshot, for the recent window. */
    private record Sample(long worldNs, long wallNs, long[] releases, long[] misses, long[] commits) {
    }

    private final JsonNodeFactory json = JsonNodeFactory.instance;
    private final Monitor monitor;
    private final RunScene scene;
    private final long startWorldNs;
    private final List<TaskInfo> tasks;
    private final List<String> keys;
    private final ArrayDeque<Sample> history = new ArrayDeque<>();
    private final TimingSeries series;
    private final List<double[]> trail = new ArrayList<>();
    private final Odometry odometry = new Odometry();
    private final LaserScan laser = new LaserScan();
    private final PlannedPath path = new PlannedPath();
    private final CourseStatus course = new CourseStatus();
    private PositionMediatorTask.MediatorCounts lastMediator;
    private String mediatorWinner = "none";
    private long seq;

    /**
     * @param monitor the monitor observed
     * @param scene the run's scene, or null for tasks and keys only
     * @param startWorldNs world time taken as the start of the run
     */
    SnapshotBuilder(Monitor monitor, RunScene scene, long startWorldNs) {
        this.monitor = monitor;
        this.scene = scene;
        this.startWorldNs = startWorldNs;
        this.tasks = monitor.tasks();
        this.keys = monitor.keyNames();
        this.series = new TimingSeries(tasks.size(), startWorldNs);
    }

    /** @return the listener that feeds the strip charts; the monitor must have it before it starts */
    TimingSeries series() {
        return series;
    }

    /**
     * @param state {@code running}, {@code stopping} or {@code finished}
     * @param truePose the robot's true pose, or null
     * @param truthKind where {@code truePose} comes from
     * @return a new snapshot
     */
    ObjectNode build(String state, Pose2d truePose, String truthKind) {
        long nowWorldNs = monitor.clock().nanos();
        long nowWallNs = System.nanoTime();
        int n = tasks.size();
        TaskCounters[] counters = new TaskCounters[n];
        long[] releases = new long[n];
        long[] misses = new long[n];
        for (int i = 0; i < n; i++) {
            counters[i] = monitor.counters(i);
            releases[i] = counters[i].releases();
            misses[i] = counters[i].misses();
        }
        FeedStats[] feeds = new FeedStats[keys.size()];
        long[] commits = new long[keys.size()];
        for (int i = 0; i < keys.size(); i++) {
            feeds[i] = monitor.feed(keys.get(i));
            commits[i] = feeds[i].commits();
        }
        Sample now = new Sample(nowWorldNs, nowWallNs, releases, misses, commits);
        Sample base = recentBase(now);

        ObjectNode root = json.objectNode();
        root.put("schema", SCHEMA);
        root.put("seq", ++seq);
        root.put("kind", scene == null ? "bench" : "run");
        root.put("state", state);
        root.put("time_s", round((nowWorldNs - startWorldNs) / 1e9, 2));
        root.put("time_scale", monitor.clock().timeScale());
        root.put("recent_window_s", round((nowWorldNs - base.worldNs()) / 1e9, 2));
        series.drain();
        long lastBin = series.binOf(nowWorldNs);
        long firstBin = Math.max(0, lastBin - TimingSeries.WINDOW_BINS + 1);
        root.put("series_bin_s", TimingSeries.BIN_NS / 1e9);
        root.put("series_from_s", firstBin * TimingSeries.BIN_NS / 1e9);
        root.put("recent_exec_runs", TaskCounters.RECENT_EXEC_RUNS);
        ArrayNode taskRows = root.putArray("tasks");
        for (int i = 0; i < n; i++) {
            ObjectNode row = taskRow(tasks.get(i), counters[i], base, now, i);
            row.set("series", seriesOf(series.bins(i), firstBin, lastBin));
            taskRows.add(row);
        }
        ArrayNode keyRows = root.putArray("keys");
        for (int i = 0; i < keys.size(); i++) {
            keyRows.add(keyRow(keys.get(i), feeds[i], base, now, i));
        }
        if (scene != null) {
            run(root, truePose, truthKind);
        }
        return root;
    }

    /** Appends {@code now} to the history and returns the oldest sample inside the recent window. */
    private Sample recentBase(Sample now) {
        history.addLast(now);
        while (history.size() > 2) {
            Iterator<Sample> it = history.iterator();
            it.next();
            Sample second = it.next();
            if (now.worldNs() - second.worldNs() >= RECENT_WORLD_NS && now.wallNs() - second.wallNs() >= RECENT_WALL_NS) {
                history.removeFirst();
            } else {
                break;
            }
        }
        return history.peekFirst();
    }

    private ObjectNode taskRow(TaskInfo task, TaskCounters c, Sample base, Sample now, int i) {
        ObjectNode row = json.objectNode();
        row.put("name", task.name());
        Schedule schedule = task.schedule();
        row.put("schedule", schedule.kind());
        Double periodMs = schedule instanceof Schedule.Periodic p ? p.periodNs() / 1e6 : null;
        if (periodMs == null) {
            row.putNull("period_ms");
        } else {
            row.put("period_ms", round(periodMs, 6)); // to the nanosecond: a 1 ns period is not 0 ms
        }
        row.put("releases", c.releases());
        row.put("runs", c.runs());
        row.put("misses", c.misses());
        row.put("miss_pct", pct(c.misses(), c.releases()));
        long recentReleases = now.releases()[i] - base.releases()[i];
        row.put("recent_releases", recentReleases);
        row.put("recent_miss_pct", pct(now.misses()[i] - base.misses()[i], recentReleases));
        row.put("skipped", c.skipped());
        row.put("stale_runs", c.staleRuns());
        row.put("errors", c.errors());
        // The p99 of the latest runs, not of the whole run (the report's exec_us.p99): a name of its own.
        row.put("recent_exec_p99_ms", round(c.recentExecP99Ns() / 1e6, 3));
        if (periodMs == null) {
            row.putNull("recent_exec_p99_of_period");
        } else {
            row.put("recent_exec_p99_of_period", round(c.recentExecP99Ns() / 1e6 / periodMs, 3));
        }
        return row;
    }

    /**
     * A task's strip chart: per bin from {@code firstBin} to {@code lastBin}, the largest release
     * lateness and execution time in ms (null where no cycle was released) and the misses.
     */
    private ObjectNode seriesOf(TimingSeries.Bins bins, long firstBin, long lastBin) {
        ObjectNode node = json.objectNode();
        ArrayNode lateness = node.putArray("lateness_max_ms");
        ArrayNode exec = node.putArray("exec_max_ms");
        ArrayNode misses = node.putArray("misses");
        for (long k = firstBin; k <= lastBin; k++) {
            if (bins.cycles(k) > 0) {
                lateness.add(round(bins.maxLatenessNs(k) / 1e6, 3));
                exec.add(round(bins.maxExecNs(k) / 1e6, 3));
            } else {
                lateness.addNull();
                exec.addNull();
            }
            misses.add(bins.misses(k));
        }
        node.put("lost_cycles", bins.lost());
        return node;
    }

    private ObjectNode keyRow(String key, FeedStats feed, Sample base, Sample now, int i) {
        ObjectNode row = json.objectNode();
        row.put("name", key);
        row.put("producer", monitor.producer(key));
        ArrayNode consumerNames = row.putArray("consumers");
        long fastestConsumerNs = 0;
        for (String consumer : monitor.consumers(key)) {
            consumerNames.add(consumer);
            Schedule s = monitor.tasks().stream().filter(t -> t.name().equals(consumer)).findFirst()
                    .orElseThrow().schedule();
            if (s instanceof Schedule.Periodic p && (fastestConsumerNs == 0 || p.periodNs() < fastestConsumerNs)) {
                fastestConsumerNs = p.periodNs();
            }
        }
        row.put("commits", feed.commits());
        row.put("rate_hz", round(feed.rateHz(), 2));
        double windowS = (now.worldNs() - base.worldNs()) / 1e9;
        long recentCommits = now.commits()[i] - base.commits()[i];
        row.put("recent_rate_hz", windowS <= 0 ? 0.0 : round(recentCommits / windowS, 2));
        if (fastestConsumerNs == 0) {
            row.putNull("consumer_rate_hz");
            row.putNull("nyquist_rate_hz");
        } else {
            row.put("consumer_rate_hz", round(1e9 / fastestConsumerNs, 2));
            row.put("nyquist_rate_hz", round(2e9 / fastestConsumerNs, 2));
        }
        return row;
    }

    private void run(ObjectNode root, Pose2d truePose, String truthKind) {
        ObjectNode run = root.putObject("run");
        run.put("scenario", scene.scenario());
        monitor.read(scene.keys().course(), course);
        run.put("waypoints_reached", course.waypointsReached);
        run.put("waypoints_total", course.waypointsTotal == 0 ? scene.waypoints().size() : course.waypointsTotal);
        run.put("distance_to_finish_m", round(course.distanceToFinishM, 2));
        run.put("done", course.done);
        String outcome = scene.outcome().get();
        if (outcome == null) {
            run.putNull("outcome");
        } else {
            run.put("outcome", outcome);
        }
        mediator(run.putObject("mediator"));

        boolean haveOdometry = monitor.read(RobotKeys.ODOMETRY, odometry) != 0;
        Pose2d pose = truePose != null ? truePose : haveOdometry ? odometry.pose() : null;
        if (pose != null) {
            ObjectNode robot = root.putObject("robot");
            robot.put("x_m", round(pose.xM(), 3));
            robot.put("y_m", round(pose.yM(), 3));
            robot.put("yaw_rad", round(pose.yawRad(), 3));
            robot.put("source", truePose != null ? truthKind : "odometry");
            extendTrail(pose);
        }
        if (haveOdometry) {
            ObjectNode odo = root.putObject("odometry");
            odo.put("x_m", round(odometry.xM, 3));
            odo.put("y_m", round(odometry.yM, 3));
            odo.put("yaw_rad", round(odometry.yawRad, 3));
            odo.put("v_mps", round(odometry.vxMps, 3));
            odo.put("omega_rad_per_s", round(odometry.omegaRadPerSec, 3));
        }
        ArrayNode trailNode = root.putArray("trail");
        for (double[] p : trail) {
            trailNode.addArray().add(p[0]).add(p[1]);
        }
        if (monitor.hasKey(RobotKeys.LASER.name()) && monitor.read(RobotKeys.LASER, laser) != 0) {
            ObjectNode scan = root.putObject("laser");
            scan.put("min_angle_rad", laser.minAngleRad);
            scan.put("increment_rad", laser.angleIncrementRad() * LASER_STRIDE);
            scan.put("max_range_m", laser.maxRangeM);
            ArrayNode ranges = scan.putArray("ranges_m");
            for (int b = 0; b < laser.count(); b += LASER_STRIDE) {
                ranges.add(round(laser.rangesM[b], 2));
            }
        }
        ArrayNode pathNode = root.putArray("path");
        if (monitor.hasKey(scene.keys().path().name()) && monitor.read(scene.keys().path(), path) != 0 && path.valid) {
            for (int k = 0; k < path.count(); k++) {
                pathNode.addArray().add(round(path.xM[k], 3)).add(round(path.yM[k], 3));
            }
        }
        ArrayNode waypoints = root.putArray("waypoints");
        for (int k = 0; k < scene.waypoints().size(); k++) {
            Point2d w = scene.waypoints().get(k);
            ObjectNode node = waypoints.addObject();
            node.put("x_m", w.xM());
            node.put("y_m", w.yM());
            node.put("reached", k < course.waypointsReached);
        }
    }

    private void mediator(ObjectNode node) {
        PositionMediatorTask.MediatorCounts counts = scene.mediator().get();
        if (lastMediator != null) {
            long obstacle = counts.obstacle() - lastMediator.obstacle();
            long waypoint = counts.waypoint() - lastMediator.waypoint();
            long stop = counts.stop() - lastMediator.stop();
            long most = Math.max(obstacle, Math.max(waypoint, stop));
            if (most > 0) {
                mediatorWinner = most == obstacle ? "obstacle" : most == waypoint ? "waypoint" : "stop";
            }
        }
        lastMediator = counts;
        node.put("winner", mediatorWinner);
        node.put("obstacle", counts.obstacle());
        node.put("waypoint", counts.waypoint());
        node.put("stop", counts.stop());
        node.put("stale_stops", counts.staleStops());
    }

    private void extendTrail(Pose2d pose) {
        double[] last = trail.isEmpty() ? null : trail.get(trail.size() - 1);
        if (last != null && Math.hypot(pose.xM() - last[0], pose.yM() - last[1]) < TRAIL_STEP_M) {
            return;
        }
        trail.add(new double[] {round(pose.xM(), 3), round(pose.yM(), 3)});
        if (trail.size() > MAX_TRAIL_POINTS) {
            // Halve the resolution of the older half, keeping the shape and a bounded size.
            List<double[]> thinned = new ArrayList<>(MAX_TRAIL_POINTS);
            int half = trail.size() / 2;
            for (int k = 0; k < half; k += 2) {
                thinned.add(trail.get(k));
            }
            thinned.addAll(trail.subList(half, trail.size()));
            trail.clear();
            trail.addAll(thinned);
        }
    }

    private static double pct(long part, long whole) {
        return whole <= 0 ? 0.0 : round(100.0 * part / whole, 2);
    }

    static double round(double v, int digits) {
        if (!Double.isFinite(v)) {
            return 0.0;
        }
        return Rounding.toDecimals(v, digits);
    }
}
