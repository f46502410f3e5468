package io.rtaware.replay;

import io.rtaware.record.RecordingPlan;
import io.rtaware.record.RunRecorder;
import io.rtaware.record.StateJsonMessage;
import io.rtaware.record.TaskCycleMessage;
import io.rtaware.record.mcap.McapChannel;
import io.rtaware.record.mcap.McapFormatException;
import io.rtaware.record.mcap.McapReader;
import io.rtaware.record.mcap.McapSummary;
import io.rtaware.record.mcap.McapVisitor;
import io.rtaware.ros2msg.cdr.CdrException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What replay needs from a recording, loaded into memory: the {@code rtaware.run} metadata, every
 * commit of the wanted keys (its world time, generation and message bytes, with the
 * {@code /rtaware/state/<key>} message of ROS 2-typed keys) and every task's cycle records.
 *
 * <p>Generations: a recording made by this version numbers each key's messages by generation
 * and each task's records from 0 (channel metadata {@code sequence}), so a commit or cycle the
 * recorder dropped shows as a gap. In older recordings generations are counted from 1 in file
 * order, which is exact only if nothing was dropped. Immutable after loading.
 */
public final class Recording {

    /**
     * One committed value.
     *
     * @param timeNs world time of the commit
     * @param generation its generation
     * @param data its message as recorded
     * @param state the JSON of what its ROS 2 message lacks, or null
     */
    public record Commit(long timeNs, long generation, byte[] data, byte[] state) {
    }

    /** One task's timing record with its number among the task's records (dropped ones included). */
    public record Cycle(long number, TaskCycleMessage message) {
    }

    /**
     * A key's channel and its commits in generation order.
     *
     * @param key the key's name
     * @param messageEncoding {@code cdr} or {@code json}
     * @param frameId the frame id of its ROS 2 header
     * @param commits its commits in generation order
     * @param generations the generation of each commit, ascending
     */
    public record KeyChannel(String key, String messageEncoding, String frameId, List<Commit> commits,
                             long[] generations) {
        /**
         * Finds a commit by generation without allocating.
         *
         * @param generation a generation
         * @return its commit, or null if the recording lacks it (dropped)
         */
        public Commit generation(long generation) {
            int i = Arrays.binarySearch(generations, generation);
            return i < 0 ? null : commits.get(i);
        }
    }

    /** A task's timing channel: its input keys (in the order of the records' generations) and records. */
    public record TaskTimeline(String task, List<String> inputs, List<Cycle> cycles) {
    }

    private final Path file;
    private final Map<String, String> runMetadata;
    private final Map<String, KeyChannel> keys;
    private final Map<String, TaskTimeline> tasks;
    private final long endNs;

    private Recording(Path file, Map<String, String> runMetadata, Map<String, KeyChannel> keys,
                      Map<String, TaskTimeline> tasks, long endNs) {
        this.file = file;
        this.runMetadata = runMetadata;
        this.keys = keys;
        this.tasks = tasks;
        this.endNs = endNs;
    }

    /**
     * Loads a recording.
     *
     * @param reader the opened file
     * @param file its path (for messages)
     * @return the recording
     * @throws McapFormatException if the file or a message in it is malformed
     * @throws IOException if it cannot be read
     */
    public static Recording load(McapReader reader, Path file) throws IOException {
        McapSummary summary = reader.summary();
        Map<String, String> metadata = new LinkedHashMap<>();
        Map<Integer, ChannelBuilder> builders = new HashMap<>();
        Map<String, ChannelBuilder> stateOf = new HashMap<>();
        Map<String, TimelineBuilder> timelines = new LinkedHashMap<>();
        long[] offsetNs = {0};
        try {
            reader.read(new McapVisitor() {
                @Override
                public void metadata(String name, Map<String, String> entries) {
                    if (name.equals("rtaware.run")) {
                        metadata.putAll(entries);
                        // Log times are world time plus this (Unix-epoch ns of world time 0); absent in older files.
                        try {
                            offsetNs[0] = Long.parseLong(entries.getOrDefault(RecordingPlan.LOG_TIME_OFFSET_NS, "0"));
                        } catch (NumberFormatException e) {
                            throw new IllegalArgumentException("metadata " + RecordingPlan.LOG_TIME_OFFSET_NS
                                    + " is not a number: " + e.getMessage());
                        }
                    }
                }

                @Override
                public void message(McapChannel channel, long sequence, long logTimeNs, long publishTimeNs,
                                    byte[] data, int offset, int length) {
                    String topic = channel.topic();
                    if (topic.startsWith(RecordingPlan.TIMING_PREFIX)) {
                        TimelineBuilder t = timelines.computeIfAbsent(topic.substring(RecordingPlan.TIMING_PREFIX.length()),
                                name -> new TimelineBuilder(channel));
                        t.add(sequence, TaskCycleMessage.decode(data, offset, length));
                        return;
                    }
                    String key = channel.metadata().get("key");
                    if (key == null) {
                        return;
                    }
                    // Since the ros2 profile, JSON values travel inside an rtaware_msgs/msg/StateJson.
                    byte[] bytes = StateJsonMessage.JSON.equals(channel.metadata().get(StateJsonMessage.VALUE_ENCODING))
                            ? StateJsonMessage.json(data, offset, length) : Arrays.copyOfRange(data, offset, offset + length);
                    long worldNs = logTimeNs - offsetNs[0];
                    if (topic.startsWith(RecordingPlan.STATE_PREFIX)) {
                        stateOf.computeIfAbsent(key, k -> new ChannelBuilder(channel)).add(sequence, worldNs, bytes);
                    } else {
                        builders.computeIfAbsent(channel.id(), id -> new ChannelBuilder(channel))
                                .add(sequence, worldNs, bytes);
                    }
                }
            });
        } catch (CdrException | IllegalArgumentException e) {
            throw new McapFormatException(file + ": a record is malformed: " + e.getMessage());
        }
        Map<String, KeyChannel> keys = new LinkedHashMap<>();
        for (ChannelBuilder b : builders.values()) {
            keys.put(b.key, b.build(stateOf.get(b.key), file));
        }
        Map<String, TaskTimeline> tasks = new LinkedHashMap<>();
        timelines.forEach((name, t) -> tasks.put(name, t.build(name)));
        return new Recording(file, Collections.unmodifiableMap(metadata), Collections.unmodifiableMap(keys),
                Collections.unmodifiableMap(tasks), summary.statistics().messageEndNs() - offsetNs[0]);
    }

    /** @return the file */
    public Path file() {
        return file;
    }

    /** @return the {@code rtaware.run} metadata entries */
    public Map<String, String> runMetadata() {
        return runMetadata;
    }

    /** @return every recorded key's channel by key name */
    public Map<String, KeyChannel> keys() {
        return keys;
    }

    /** @return every task's timing by task name, in file order */
    public Map<String, TaskTimeline> tasks() {
        return tasks;
    }

    /** @return the log time of the last message, world ns */
    public long endNs() {
        return endNs;
    }

    /** Collects one key channel's messages. */
    private static final class ChannelBuilder {
        final String key;
        final String encoding;
        final String frame;
        final boolean numbered;
        final List<long[]> stamps = new ArrayList<>();
        final List<byte[]> data = new ArrayList<>();

        ChannelBuilder(McapChannel channel) {
            key = channel.metadata().get("key");
            encoding = StateJsonMessage.JSON.equals(channel.metadata().get(StateJsonMessage.VALUE_ENCODING))
                    ? StateJsonMessage.JSON : channel.messageEncoding();
            frame = channel.metadata().getOrDefault("frame_id", "map");
            numbered = RunRecorder.SEQUENCE_GENERATION.equals(channel.metadata().get(RunRecorder.SEQUENCE));
        }

        void add(long sequence, long timeNs, byte[] bytes) {
            long generation = numbered ? sequence : data.size() + 1;
            stamps.add(new long[] {generation, timeNs});
            data.add(bytes);
        }

        KeyChannel build(ChannelBuilder state, Path file) throws McapFormatException {
            Map<Long, byte[]> stateByGeneration = new HashMap<>();
            if (state != null) {
                for (int i = 0; i < state.data.size(); i++) {
                    stateByGeneration.put(state.stamps.get(i)[0], state.data.get(i));
                }
            }
            List<Commit> commits = new ArrayList<>(data.size());
            for (int i = 0; i < data.size(); i++) {
                long generation = stamps.get(i)[0];
                byte[] s = stateByGeneration.get(generation);
                if (state != null && s == null) {
                    continue; // the value without its state message cannot be rebuilt: as if dropped
                }
                commits.add(new Commit(stamps.get(i)[1], generation, data.get(i), s));
            }
            commits.sort(Comparator.comparingLong(Commit::generation));
            long[] generations = new long[commits.size()];
            for (int i = 0; i < generations.length; i++) {
                generations[i] = commits.get(i).generation();
                if (i > 0 && generations[i] == generations[i - 1]) {
                    throw new McapFormatException(file + ": key '" + key + "' has generation " + generations[i] + " twice");
                }
            }
            return new KeyChannel(key, encoding, frame, List.copyOf(commits), generations);
        }
    }

    /** Collects one task's timing records. */
    private static final class TimelineBuilder {
        final List<String> inputs;
        final boolean numbered;
        final List<Cycle> cycles = new ArrayList<>();

        TimelineBuilder(McapChannel channel) {
            String names = channel.metadata().getOrDefault("inputs", "");
            inputs = names.isEmpty() ? List.of() : List.of(names.split(","));
            numbered = RunRecorder.SEQUENCE_CYCLE.equals(channel.metadata().get(RunRecorder.SEQUENCE));
        }

        void add(long sequence, TaskCycleMessage m) {
            if (!m.outcome().equals("skipped") && m.inputGenerations().length != inputs.size()) {
                throw new IllegalArgumentException("a cycle record has " + m.inputGenerations().length
                        + " input generations for " + inputs.size() + " inputs");
            }
            cycles.add(new Cycle(numbered ? sequence : cycles.size(), m));
        }

        TaskTimeline build(String task) {
            cycles.sort(Comparator.comparingLong(Cycle::number));
            return new TaskTimeline(task, inputs, List.copyOf(cycles));
        }
    }
}
