package io.rtaware.bench.load;

import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Durations;
import io.rtaware.replay.AdviceCheck;
import io.rtaware.replay.Recording;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A recording of {@code rtaware bench --record}, its task set rebuilt for what-if replays from
 * the {@code rtaware.run} metadata ({@code tasks}: {@code name:period:work,...}) and each task's
 * recorded inputs (in a chain, the previous task's output). The tasks do no work of their own: a
 * what-if replay charges each cycle its task's recorded execution time. Stateless.
 */
public final class BenchRecording {

    /** The {@code command} metadata entry of a bench recording. */
    public static final String COMMAND = "bench";

    private BenchRecording() {
    }

    /**
     * @param recording a recording
     * @return true if {@code rtaware bench --record} made it
     */
    public static boolean is(Recording recording) {
        return COMMAND.equals(recording.runMetadata().get("command"));
    }

    /**
     * @param recording a bench recording
     * @param file its path, for messages
     * @return the task set, at the periods a replay asks for
     * @throws IllegalArgumentException if its {@code tasks} metadata is missing or malformed
     */
    public static AdviceCheck.Controller controller(Recording recording, Path file) {
        String tasks = recording.runMetadata().get("tasks");
        if (tasks == null || tasks.isBlank()) {
            throw new IllegalArgumentException(file + ": its rtaware.run metadata has no 'tasks' (name:period:work,...)");
        }
        Map<String, Long> periodsNs = new LinkedHashMap<>();
        Map<String, String> upstream = new LinkedHashMap<>();
        for (String entry : tasks.split(",")) {
            String[] parts = entry.split(":");
            try {
                periodsNs.put(parts[0], Durations.parseNanos(parts[1]));
            } catch (RuntimeException e) {
                throw new IllegalArgumentException(file + ": task entry '" + entry + "' of its metadata is not name:period:work");
            }
            Recording.TaskTimeline timeline = recording.tasks().get(parts[0]);
            if (timeline != null && !timeline.inputs().isEmpty()) {
                String input = timeline.inputs().get(0);
                upstream.put(parts[0], input.endsWith(".out") ? input.substring(0, input.length() - 4) : input);
            }
        }
        BusyWork idle = BusyWork.calibrate();
        return periods -> {
            List<TaskSpec> specs = new ArrayList<>();
            periodsNs.forEach((name, recorded) -> specs.add(new TaskSpec(name,
                    Schedule.periodic(periods.getOrDefault(name, recorded)), ErrorPolicy.CONTINUE,
                    new BenchTask(name, 0, upstream.get(name), idle))));
            return specs;
        };
    }
}
