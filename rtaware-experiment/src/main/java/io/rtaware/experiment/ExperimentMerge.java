package io.rtaware.experiment;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * Merges the folders of one plan's shards (made with {@code experiment --shard K/N} on several
 * machines) into one experiment folder: {@code results.csv} with every row in the whole plan's
 * order (so its statistics are those of the same runs made in one folder), each run's folder,
 * {@code experiment.json} (the machines of all shards) and {@code plan.json}.
 *
 * <p>Folders of different plans are refused: the scenario, time scale, seed, grid and design must be
 * equal; where two folders have a {@code plan.json}, their sets (names, periods, top speeds) and
 * runs per set must be equal; every row's set must be the set of that number in the plan; and no
 * run may be in two folders. Each folder must pass {@link FolderCheck} (not being written, no
 * impossible value, every row a run of its own plan and shard).
 */
public final class ExperimentMerge {

    private ExperimentMerge() {
    }

    /**
     * @param dirs the folders to merge, at least one
     * @param out a new folder (no {@code results.csv} yet, none of {@code dirs})
     * @return the merged rows, in the whole plan's order (run 1 of every set, then run 2, ...)
     * @throws IOException if reading or writing fails
     * @throws ExperimentInputException if a folder is not an experiment, the folders are of
     *     different plans, a run is in two folders, or {@code out} is not new
     */
    public static List<RunResult> merge(List<Path> dirs, Path out) throws IOException {
        for (Path dir : dirs) {
            if (dir.toAbsolutePath().normalize().equals(out.toAbsolutePath().normalize())) {
                throw new ExperimentInputException("--out " + out + " is one of the folders to merge; give a new folder");
            }
        }
        if (Files.exists(out.resolve(ResultsCsv.FILE_NAME))) {
            throw new ExperimentInputException("--out " + out + " already holds a " + ResultsCsv.FILE_NAME + "; give a new folder");
        }
        List<Folder> folders = new ArrayList<>();
        for (Path dir : dirs) {
            folders.add(Folder.read(dir));
        }
        Folder first = folders.get(0);
        Optional<ExperimentPlan> plan = folders.stream().map(Folder::plan).flatMap(Optional::stream).findFirst();
        Map<Integer, PeriodSet> sets = new TreeMap<>();
        plan.ifPresent(p -> {
            for (int i = 0; i < p.sets().size(); i++) {
                sets.put(i + 1, p.sets().get(i));
            }
        });
        Map<String, Path> owner = new HashMap<>();
        List<Located> rows = new ArrayList<>();
        for (Folder f : folders) {
            checkSamePlan(first, f);
            if (plan.isPresent() && f.plan().isPresent()) {
                checkSameSets(plan.get(), f);
            }
            for (RunResult r : f.rows()) {
                PeriodSet known = sets.putIfAbsent(r.set(), r.periods());
                if (known != null && !(known.name().equals(r.periods().name()) && known.sameRunsAs(r.periods()))) {
                    throw new ExperimentInputException("cannot merge " + f.dir() + ": its set " + r.set() + " is '"
                            + r.periods().name() + "' (" + r.periods().label() + "), elsewhere '" + known.name() + "' ("
                            + known.label() + "): different plans");
                }
                Path other = owner.putIfAbsent(r.set() + "/" + r.run(), f.dir());
                if (other != null) {
                    throw new ExperimentInputException("cannot merge: set " + r.set() + " run " + r.run() + " is in both "
                            + other + " and " + f.dir() + " (the same shard twice?)");
                }
                rows.add(new Located(r, f.dir()));
            }
        }
        rows.sort(Comparator.comparingInt((Located l) -> l.row().run()).thenComparingInt(l -> l.row().set()));
        write(out, rows, folders, plan);
        return rows.stream().map(Located::row).toList();
    }

    private static void checkSamePlan(Folder a, Folder b) {
        RunConditions x = a.conditions();
        RunConditions y = b.conditions();
        if (!x.scenario().equals(y.scenario()) || x.timeScale() != y.timeScale() || x.seed() != y.seed()
                || !Objects.equals(x.gridResolutionM(), y.gridResolutionM()) || x.design() != y.design()
                || !Objects.equals(x.cpuLimitCpus(), y.cpuLimitCpus())) {
            throw new ExperimentInputException("cannot merge " + a.dir() + " (scenario " + x.scenario() + ", time scale "
                    + x.timeScale() + ", seed " + x.seed() + ", grid " + x.gridResolutionM() + ", design "
                    + x.design().label() + ") and " + b.dir() + " (scenario " + y.scenario() + ", time scale "
                    + y.timeScale() + ", seed " + y.seed() + ", grid " + y.gridResolutionM() + ", design "
                    + y.design().label() + "): different plans");
        }
    }

    private static void checkSameSets(ExperimentPlan plan, Folder f) {
        ExperimentPlan other = f.plan().orElseThrow();
        boolean same = plan.sets().size() == other.sets().size() && plan.runsPerSet() == other.runsPerSet();
        for (int i = 0; same && i < plan.sets().size(); i++) {
            PeriodSet a = plan.sets().get(i);
            PeriodSet b = other.sets().get(i);
            same = a.name().equals(b.name()) && a.sameRunsAs(b);
        }
        if (!same) {
            throw new ExperimentInputException("cannot merge " + f.dir() + ": its plan (" + describe(other)
                    + ") is not that of the other folders (" + describe(plan) + "): different plans");
        }
    }

    private static String describe(ExperimentPlan p) {
        List<String> sets = p.sets().stream().map(PeriodSet::label).toList();
        return p.sets().size() + " sets " + String.join(", ", sets) + " x " + p.runsPerSet() + " runs";
    }

    private static void write(Path out, List<Located> rows, List<Folder> folders, Optional<ExperimentPlan> plan)
            throws IOException {
        Files.createDirectories(out.resolve(ExperimentRunner.RUNS_DIR));
        StringBuilder csv = new StringBuilder(String.join(",", ResultsCsv.HEADER)).append('\n');
        for (Located l : rows) {
            csv.append(ResultsCsv.format(l.row())).append('\n');
            String name = new PlannedRun(l.row().set(), l.row().run(), l.row().periods()).folderName();
            copyTree(l.dir().resolve(ExperimentRunner.RUNS_DIR).resolve(name), out.resolve(ExperimentRunner.RUNS_DIR).resolve(name));
        }
        Files.writeString(out.resolve(ResultsCsv.FILE_NAME), csv, StandardCharsets.UTF_8);
        List<RunResult> merged = rows.stream().map(Located::row).toList();
        Set<String> machines = new LinkedHashSet<>();
        ExperimentProfile profile = null;
        for (Folder f : folders) {
            Optional<ExperimentProfile> p = ExperimentProfile.read(f.dir());
            if (p.isPresent()) {
                profile = profile == null ? p.get() : profile;
                if (p.get().machine() != null) {
                    machines.add(p.get().machine());
                }
            }
        }
        if (profile == null && !merged.isEmpty()) {
            profile = ExperimentProfile.fromResults(merged);
        }
        if (profile != null) {
            int runs = plan.map(ExperimentPlan::runsPerSet).orElse(profile.runsPerSet());
            profile.withRunsAndMachine(runs, machines.isEmpty() ? null : String.join(" + ", machines)).write(out);
        }
        if (plan.isPresent()) {
            ExperimentPlan p = plan.get();
            PlanFile.write(out, new ExperimentPlan(p.sets(), p.runsPerSet(), p.conditions(), Shard.WHOLE));
        }
    }

    private static void copyTree(Path from, Path to) throws IOException {
        if (!Files.isDirectory(from)) {
            return;
        }
        try (var paths = Files.walk(from)) {
            for (Path p : paths.toList()) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
    }

    private record Located(RunResult row, Path dir) {
    }

    /** One folder to merge: its rows, its plan if recorded, and the conditions its runs share. */
    private record Folder(Path dir, List<RunResult> rows, Optional<ExperimentPlan> plan, RunConditions conditions) {

        static Folder read(Path dir) throws IOException {
            Path csv = dir.resolve(ResultsCsv.FILE_NAME);
            List<RunResult> rows = FolderCheck.rows(dir).stream().map(ResultsCsv.Row::result).toList();
            Optional<ExperimentPlan> plan = PlanFile.read(dir);
            RunConditions conditions = plan.map(ExperimentPlan::conditions)
                    .orElseGet(() -> rows.isEmpty() ? null : rows.get(0).conditions());
            if (conditions == null) {
                throw new ExperimentInputException(csv + " has no runs and " + dir + " has no " + PlanFile.FILE_NAME
                        + ": nothing to merge");
            }
            for (RunResult r : rows) {
                RunConditions c = r.conditions();
                if (!c.equals(conditions)) {
                    throw new ExperimentInputException(csv + " (set " + r.set() + " run " + r.run() + ") was made with scenario "
                            + c.scenario() + ", time scale " + c.timeScale() + ", seed " + c.seed() + ", grid "
                            + c.gridResolutionM() + ", unlike the rest of its folder: different plans");
                }
            }
            return new Folder(dir, rows, plan, conditions);
        }
    }
}
