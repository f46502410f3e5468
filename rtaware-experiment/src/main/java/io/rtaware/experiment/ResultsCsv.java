package io.rtaware.experiment;

import java.io.IOException;
import java.io.RandomAccessFile;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * {@code results.csv}: one row per finished run, appended (and flushed) as each run ends, so an
 * interrupted experiment loses nothing that finished. Columns, in order:
 *
 * <pre>
 * set, set_name, run, scenario, time_scale, seed, grid_resolution_m,
 * waypoint_period_ms, obstacle_period_ms, occupancy_period_ms, planner_period_ms,
 * outcome, run_time_s, distance_to_finish_m, distance_travelled_m, collisions,
 * waypoints_reached, waypoints_total,
 * then for each task T of waypoint, obstacle, occupancy, planner:
 * T_releases, T_misses, T_miss_pct, T_stale_runs, T_exec_p99_us,
 * then (added later, so appended): top_speed_mps, T_skipped for each task,
 * mediator_obstacle_cycles, mediator_waypoint_cycles, mediator_stop_cycles,
 * T_max_safe_period_ms for each task, robot_seed (the run's), robots (the plan's count),
 * min_clearance_m (the nearest the robot's body came to any obstacle), near_misses (approaches
 * within the simulator's 0.05 m margin that did not touch),
 * machine, machine_reasons, other_cpus, steal_pct, load_start, load_end, gc_max_pause_ms,
 * time_to_safepoint_max_ms, machine_before_run, waited_for_quiet_s (the run's conditions:
 * {@link RunMachine}; {@code machine} is empty in rows that predate them), machine_cpus (the CPUs
 * the run's conditions counted; empty in rows that predate it), design ({@link ExperimentDesign}'s
 * label; empty in rows that predate it, which are all {@code blocked}), started_utc, ended_utc
 * (when the run's process started and ended, ISO-8601 UTC: {@link RunTimes}), check_other_cpus,
 * check_steal_pct, check_load (the figures of the quiet check's last look before the run, those its
 * rule judged: {@link MachineCheck.Reading}); all empty in rows that predate them), cpu_limit_cpus
 * (the CPU quota the run's JVM ran under, {@code --cpu-limit}; empty for none
 * </pre>
 *
 * {@code seed} and {@code robot_seed} are the run's own world seed and robot seed, as passed to
 * {@code rtaware run}.
 *
 * RFC 4180 quoting; an empty field is a value the run did not give (an {@code error} row, or
 * {@code grid_resolution_m} when {@code run}'s default was used). Numbers are written exactly
 * (shortest decimal that reads back to the same double). A file written before the appended
 * columns existed still reads: its header is a prefix of today's, and a missing column is an
 * empty value.
 */
public final class ResultsCsv {

    /** The file name inside an experiment folder. */
    public static final String FILE_NAME = "results.csv";

    private static final List<String> TASK_COLUMNS = List.of("releases", "misses", "miss_pct", "stale_runs", "exec_p99_us");

    private static final List<String> MACHINE_COLUMNS = List.of("machine", "machine_reasons", "other_cpus", "steal_pct",
            "load_start", "load_end", "gc_max_pause_ms", "time_to_safepoint_max_ms", "machine_before_run",
            "waited_for_quiet_s", "machine_cpus");

    /** The header row's column names. */
    public static final List<String> HEADER = header();

    /** The columns of the first version of the file; newer columns are appended after these. */
    static final int FIRST_VERSION_COLUMNS = HEADER.indexOf("top_speed_mps");

    private ResultsCsv() {
    }

    private static List<String> header() {
        List<String> h = new ArrayList<>(List.of("set", "set_name", "run", "scenario", "time_scale", "seed", "grid_resolution_m"));
        for (String task : PeriodSet.TASKS) {
            h.add(task + "_period_ms");
        }
        h.addAll(List.of("outcome", "run_time_s", "distance_to_finish_m", "distance_travelled_m", "collisions",
                "waypoints_reached", "waypoints_total"));
        for (String task : PeriodSet.TASKS) {
            for (String c : TASK_COLUMNS) {
                h.add(task + "_" + c);
            }
        }
        h.add("top_speed_mps");
        for (String task : PeriodSet.TASKS) {
            h.add(task + "_skipped");
        }
        for (String winner : RunResult.MEDIATOR_WINNERS) {
            h.add("mediator_" + winner + "_cycles");
        }
        for (String task : PeriodSet.TASKS) {
            h.add(task + "_max_safe_period_ms");
        }
        h.addAll(List.of("robot_seed", "robots", "min_clearance_m", "near_misses"));
        h.addAll(MACHINE_COLUMNS);
        h.addAll(List.of("design", "started_utc", "ended_utc", "check_other_cpus", "check_steal_pct", "check_load",
                "cpu_limit_cpus"));
        return List.copyOf(h);
    }

    /**
     * Appends one row, writing the header first if the file is new, and dropping a partial last
     * line left by a process that was killed while writing.
     *
     * @param file the results file
     * @param result the finished run
     * @throws IOException if writing fails
     */
    public static void append(Path file, RunResult result) throws IOException {
        repairPartialLine(file);
        upgradeHeader(file);
        StringBuilder text = new StringBuilder();
        if (!Files.exists(file) || Files.size(file) == 0) {
            text.append(String.join(",", HEADER)).append('\n');
        }
        text.append(format(result)).append('\n');
        Files.writeString(file, text, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND,
                StandardOpenOption.WRITE, StandardOpenOption.DSYNC);
    }

    /**
     * Rewrites a file made before the appended columns existed with today's header (its rows
     * get empty values there), so that new rows can be appended to it; atomic where the file
     * system allows.
     */
    private static void upgradeHeader(Path file) throws IOException {
        if (!Files.exists(file) || Files.size(file) == 0) {
            return;
        }
        String first = Files.readAllLines(file, StandardCharsets.UTF_8).get(0);
        if (split(first).equals(HEADER)) {
            return;
        }
        StringBuilder text = new StringBuilder(String.join(",", HEADER)).append('\n');
        for (RunResult r : read(file)) {
            text.append(format(r)).append('\n');
        }
        Path tmp = file.resolveSibling(file.getFileName() + ".upgrade");
        Files.writeString(tmp, text, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING,
                StandardOpenOption.WRITE, StandardOpenOption.DSYNC);
        try {
            Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        } catch (java.nio.file.AtomicMoveNotSupportedException e) {
            Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static void repairPartialLine(Path file) throws IOException {
        if (!Files.exists(file) || Files.size(file) == 0) {
            return;
        }
        try (RandomAccessFile raf = new RandomAccessFile(file.toFile(), "rw")) {
            long length = raf.length();
            long pos = length - 1;
            raf.seek(pos);
            if (raf.read() == '\n') {
                return;
            }
            while (pos > 0) {
                raf.seek(pos - 1);
                if (raf.read() == '\n') {
                    break;
                }
                pos--;
            }
            raf.setLength(pos);
        }
    }

    /**
     * @param r a run
     * @return its CSV row, without the line end
     */
    public static String format(RunResult r) {
        List<String> f = new ArrayList<>();
        f.add(Integer.toString(r.set()));
        f.add(quote(r.periods().name()));
        f.add(Integer.toString(r.run()));
        f.add(quote(r.conditions().scenario()));
        f.add(number(r.conditions().timeScale()));
        f.add(Long.toString(r.worldSeed()));
        f.add(r.conditions().gridResolutionM() == null ? "" : number(r.conditions().gridResolutionM()));
        r.periods().periodsMs().values().forEach(p -> f.add(Long.toString(p)));
        f.add(quote(r.outcome()));
        f.add(number(r.runTimeS()));
        f.add(number(r.distanceToFinishM()));
        f.add(number(r.distanceTravelledM()));
        f.add(integer(r.collisions()));
        f.add(integer(r.waypointsReached()));
        f.add(integer(r.waypointsTotal()));
        for (String task : PeriodSet.TASKS) {
            TaskResult t = r.tasks().get(task);
            if (t == null) {
                TASK_COLUMNS.forEach(c -> f.add(""));
            } else {
                f.add(Long.toString(t.releases()));
                f.add(Long.toString(t.misses()));
                f.add(number(t.missPct()));
                f.add(Long.toString(t.staleRuns()));
                f.add(number(t.execP99Us()));
            }
        }
        Double speed = r.periods().topSpeedMps();
        f.add(speed == null ? "" : number(speed));
        for (String task : PeriodSet.TASKS) {
            TaskResult t = r.tasks().get(task);
            f.add(t == null || t.skipped() == null ? "" : Long.toString(t.skipped()));
        }
        for (String winner : RunResult.MEDIATOR_WINNERS) {
            Long cycles = r.mediatorCycles().get(winner);
            f.add(cycles == null ? "" : cycles.toString());
        }
        for (String task : PeriodSet.TASKS) {
            TaskResult t = r.tasks().get(task);
            f.add(t == null || t.maxSafePeriodMs() == null ? "" : number(t.maxSafePeriodMs()));
        }
        f.add(Long.toString(r.robotSeed()));
        f.add(Integer.toString(r.conditions().robots()));
        f.add(r.minClearanceM() == null ? "" : number(r.minClearanceM()));
        f.add(r.nearMisses() == null ? "" : r.nearMisses().toString());
        RunMachine m = r.machine();
        boolean recorded = !RunMachine.UNRECORDED.equals(m.machine());
        f.add(recorded ? quote(m.machine()) : "");
        f.add(quote(m.reasons()));
        f.add(number(m.otherCpus()));
        f.add(number(m.stealPct()));
        f.add(number(m.loadStart()));
        f.add(number(m.loadEnd()));
        f.add(number(m.gcMaxPauseMs()));
        f.add(number(m.timeToSafepointMaxMs()));
        f.add(quote(m.beforeRun()));
        f.add(recorded || !m.beforeRun().isEmpty() ? number(m.waitedS()) : "");
        f.add(m.machineCpus() > 0 ? Integer.toString(m.machineCpus()) : "");
        f.add(r.conditions().design().label());
        f.add(RunTimes.format(r.times().startedUtc()));
        f.add(RunTimes.format(r.times().endedUtc()));
        f.add(number(m.checkOtherCpus()));
        f.add(number(m.checkStealPct()));
        f.add(number(m.checkLoad()));
        f.add(r.conditions().cpuLimitCpus() == null ? "" : number(r.conditions().cpuLimitCpus()));
        return String.join(",", f);
    }

    /**
     * A row of the file and the line it is on (the header is line 1).
     *
     * @param line the line number
     * @param result the run
     */
    public record Row(int line, RunResult result) {
    }

    /**
     * Reads every complete row. A last line without its line end (a write cut short) is not a
     * run: {@link #tornLastLine} says so, for the caller to report.
     *
     * @param file a results file written by {@link #append}
     * @return the runs, in file order
     * @throws IOException if the file cannot be read
     * @throws ExperimentInputException if it is not an rtaware results file, or a row repeats a
     *     (set, run) of an earlier row, or gives a set other periods or another name than an
     *     earlier row (the message names both lines)
     */
    public static List<RunResult> read(Path file) throws IOException {
        return readRows(file).stream().map(Row::result).toList();
    }

    /**
     * @param file a results file
     * @return a description of its last line when that line has no line end (a write cut short,
     *     e.g. a process killed while appending), naming the line number; empty otherwise
     * @throws IOException if the file cannot be read
     */
    public static java.util.Optional<String> tornLastLine(Path file) throws IOException {
        if (!Files.exists(file)) {
            return java.util.Optional.empty();
        }
        String text = Utf8Text.read(file, "results file");
        if (text.isEmpty() || text.endsWith("\n")) {
            return java.util.Optional.empty();
        }
        long line = text.lines().count();
        String last = text.substring(text.lastIndexOf('\n') + 1);
        return java.util.Optional.of(file + " line " + line + " is incomplete (" + last.length()
                + " characters without a line end: a write cut short); it is not counted as a run"
                + " and is removed when the next run is appended");
    }

    /**
     * Like {@link #read} with each row's line number.
     *
     * @param file a results file written by {@link #append}
     * @return the rows, in file order
     * @throws IOException if the file cannot be read
     * @throws ExperimentInputException as {@link #read}
     */
    public static List<Row> readRows(Path file) throws IOException {
        String text = Utf8Text.read(file, "results file");
        List<String> lines = new ArrayList<>(text.lines().toList());
        if (!text.isEmpty() && !text.endsWith("\n")) {
            lines.remove(lines.size() - 1);
        }
        if (lines.isEmpty()) {
            return List.of();
        }
        List<String> header = split(lines.get(0));
        if (header.size() < FIRST_VERSION_COLUMNS || header.size() > HEADER.size()
                || !header.equals(HEADER.subList(0, header.size()))) {
            throw new ExperimentInputException(file + ": the header is not that of rtaware's results.csv (expected "
                    + String.join(",", HEADER.subList(0, 4)) + ",...)");
        }
        List<Row> rows = new ArrayList<>();
        Map<String, Integer> lineOfRun = new java.util.HashMap<>();
        Map<Integer, Row> firstOfSet = new java.util.HashMap<>();
        for (int i = 1; i < lines.size(); i++) {
            if (lines.get(i).isBlank()) {
                continue;
            }
            RunResult r;
            try {
                r = parse(split(lines.get(i)), header.size());
            } catch (RuntimeException e) {
                throw new ExperimentInputException(file + " line " + (i + 1) + ": " + e.getMessage());
            }
            Integer earlier = lineOfRun.putIfAbsent(r.set() + "/" + r.run(), i + 1);
            if (earlier != null) {
                throw new ExperimentInputException(file + " line " + (i + 1) + ": set " + r.set() + " run " + r.run()
                        + " is already on line " + earlier + " (two processes wrote the folder?); delete one of the rows");
            }
            Row first = firstOfSet.putIfAbsent(r.set(), new Row(i + 1, r));
            if (first != null && !first.result().periods().equals(r.periods())) {
                throw new ExperimentInputException(file + " line " + (i + 1) + ": set " + r.set() + " is '"
                        + r.periods().name() + "' " + r.periods().shortLabel() + " but line " + first.line() + " has it as '"
                        + first.result().periods().name() + "' " + first.result().periods().shortLabel()
                        + "; a folder holds one plan");
            }
            rows.add(new Row(i + 1, r));
        }
        return rows;
    }

    private static RunResult parse(List<String> f, int columns) {
        if (f.size() != columns) {
            throw new IllegalArgumentException("expected " + columns + " fields, got " + f.size());
        }
        Map<String, String> row = new LinkedHashMap<>();
        for (int i = 0; i < HEADER.size(); i++) {
            row.put(HEADER.get(i), i < columns ? f.get(i) : "");
        }
        int run = Integer.parseInt(row.get("run"));
        Map<String, Long> periods = new LinkedHashMap<>();
        PeriodSet.TASKS.forEach(t -> periods.put(t, Long.parseLong(row.get(t + "_period_ms"))));
        String grid = row.get("grid_resolution_m");
        String robotSeed = row.get("robot_seed");
        String robotsText = row.get("robots");
        int robots = robotsText.isEmpty() ? 1 : Integer.parseInt(robotsText);
        int setNumber = Integer.parseInt(row.get("set"));
        ExperimentDesign design = row.get("design").isEmpty() ? ExperimentDesign.BLOCKED
                : ExperimentDesign.parse(row.get("design"));
        long worldSeed = Long.parseLong(row.get("seed"));
        long firstRobotSeed = robotSeed.isEmpty() ? RunConditions.DEFAULT_ROBOT_SEED
                : Long.parseLong(robotSeed) - design.robotIndex(worldSeed, run, robots);
        RunConditions conditions = new RunConditions(row.get("scenario"), Double.parseDouble(row.get("time_scale")),
                design.planSeed(worldSeed, setNumber, run), grid.isEmpty() ? null : Double.parseDouble(grid),
                firstRobotSeed, robots, design, optionalDouble(row.get("cpu_limit_cpus")));
        Map<String, TaskResult> tasks = new LinkedHashMap<>();
        for (String t : PeriodSet.TASKS) {
            if (!row.get(t + "_releases").isEmpty()) {
                tasks.put(t, new TaskResult(Long.parseLong(row.get(t + "_releases")), Long.parseLong(row.get(t + "_misses")),
                        decimal(row.get(t + "_miss_pct")), Long.parseLong(row.get(t + "_stale_runs")),
                        decimal(row.get(t + "_exec_p99_us")), optionalLong(row.get(t + "_skipped")),
                        optionalDouble(row.get(t + "_max_safe_period_ms"))));
            }
        }
        Map<String, Long> mediator = new LinkedHashMap<>();
        for (String winner : RunResult.MEDIATOR_WINNERS) {
            Long cycles = optionalLong(row.get("mediator_" + winner + "_cycles"));
            if (cycles != null) {
                mediator.put(winner, cycles);
            }
        }
        String speed = row.get("top_speed_mps");
        PeriodSet set = new PeriodSet(row.get("set_name"), periods, speed.isEmpty() ? null : Double.valueOf(speed));
        RunMachine machine = row.get("machine").isEmpty() ? checkOnly(row) : new RunMachine(row.get("machine"), row.get("machine_reasons"), decimal(row.get("other_cpus")),
                        decimal(row.get("steal_pct")), decimal(row.get("load_start")), decimal(row.get("load_end")),
                        decimal(row.get("gc_max_pause_ms")), decimal(row.get("time_to_safepoint_max_ms")),
                        row.get("machine_before_run"), row.get("waited_for_quiet_s").isEmpty() ? 0
                        : Double.parseDouble(row.get("waited_for_quiet_s")),
                        row.get("machine_cpus").isEmpty() ? 0 : Integer.parseInt(row.get("machine_cpus")),
                        decimal(row.get("check_other_cpus")), decimal(row.get("check_steal_pct")),
                        decimal(row.get("check_load")));
        machine.impossible().ifPresent(why -> {
            throw new IllegalArgumentException(why);
        });
        return new RunResult(setNumber, run, set, conditions,
                row.get("outcome"), decimal(row.get("run_time_s")), decimal(row.get("distance_to_finish_m")),
                decimal(row.get("distance_travelled_m")), optionalInt(row.get("collisions")),
                optionalInt(row.get("waypoints_reached")), optionalInt(row.get("waypoints_total")), tasks, mediator,
                optionalDouble(row.get("min_clearance_m")), optionalLong(row.get("near_misses")), machine,
                new RunTimes(RunTimes.parse(row.get("started_utc")), RunTimes.parse(row.get("ended_utc"))));
    }

    /**
     * The machine of a row without the run's own conditions (an {@code error} run, or a row that
     * predates them): only what the check before it found, if it was recorded.
     */
    private static RunMachine checkOnly(Map<String, String> row) {
        String before = row.get("machine_before_run");
        if (before.isEmpty()) {
            return RunMachine.NOT_RECORDED;
        }
        String waited = row.get("waited_for_quiet_s");
        return RunMachine.NOT_RECORDED.withCheck(new QuietGate.Passage(before, waited.isEmpty() ? 0 : Double.parseDouble(waited),
                "", decimal(row.get("check_other_cpus")), decimal(row.get("check_steal_pct")),
                decimal(row.get("check_load"))));
    }

    private static String number(double v) {
        if (!Double.isFinite(v)) {
            return "";
        }
        return BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }

    private static String integer(Integer v) {
        return v == null ? "" : v.toString();
    }

    private static double decimal(String s) {
        return s.isEmpty() ? Double.NaN : Double.parseDouble(s);
    }

    private static Integer optionalInt(String s) {
        return s.isEmpty() ? null : Integer.valueOf(s);
    }

    private static Double optionalDouble(String s) {
        return s.isEmpty() ? null : Double.valueOf(s);
    }

    private static Long optionalLong(String s) {
        return s.isEmpty() ? null : Long.valueOf(s);
    }

    private static String quote(String text) {
        String s = text.replace('\n', ' ').replace('\r', ' ');
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }

    /**
     * @param line one CSV line (RFC 4180 quoting, no embedded line ends)
     * @return its fields
     */
    static List<String> split(String line) {
        List<String> fields = new ArrayList<>();
        StringBuilder field = new StringBuilder();
        boolean quoted = false;
        for (int i = 0; i < line.length(); i++) {
            char c = line.charAt(i);
            if (quoted) {
                if (c == '"' && i + 1 < line.length() && line.charAt(i + 1) == '"') {
                    field.append('"');
                    i++;
                } else if (c == '"') {
                    quoted = false;
                } else {
                    field.append(c);
                }
            } else if (c == '"') {
                quoted = true;
            } else if (c == ',') {
                fields.add(field.toString());
                field.setLength(0);
            } else {
                field.append(c);
            }
        }
        fields.add(field.toString());
        return fields;
    }
}
