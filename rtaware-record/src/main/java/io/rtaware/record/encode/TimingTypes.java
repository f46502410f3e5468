package io.rtaware.record.encode;

import io.rtaware.ros2msg.MessageDefinition;

/**
 * rtaware's own message types for timing, as ROS 2 message definitions (schema encoding
 * {@code ros2msg}, message encoding {@code cdr}), so that every MCAP ROS 2 reader, Foxglove
 * included, decodes them from the definition in the file with no plug-in.
 */
public final class TimingTypes {

    /** Outcome of a cycle that finished by its deadline, read new data and did not throw. */
    public static final String OK = "ok";
    /** Outcome of a cycle that finished after its deadline. */
    public static final String MISS = "miss";
    /** Outcome recorded for releases skipped because the task was still running. */
    public static final String SKIPPED = "skipped";
    /** Outcome of a cycle whose inputs had no new data. */
    public static final String STALE = "stale";
    /** Outcome of a cycle that threw. */
    public static final String ERROR = "error";

    /** One task cycle: {@code /rtaware/timing/<task>}. */
    public static final MessageDefinition TASK_CYCLE = new MessageDefinition("rtaware_msgs/msg/TaskCycle",
            "# One cycle of an rtaware task; times are world time in ns since the clock's epoch.\n"
                    + "int64 release_ns\n"
                    + "int64 start_ns\n"
                    + "int64 end_ns\n"
                    + "# start - release in milliseconds (0 if the cycle started on time)\n"
                    + "float64 lateness\n"
                    + "# end - start in milliseconds\n"
                    + "float64 exec\n"
                    + "# ok | miss | skipped | stale | error\n"
                    + "string outcome\n"
                    + "# releases skipped (outcome skipped only)\n"
                    + "int64 skipped_releases\n"
                    + "# generation of each input read, in the order of the channel's 'inputs' metadata (0: never written)\n"
                    + "int64[] input_generations\n");

    /** One monitor event: {@code /rtaware/events}. */
    public static final MessageDefinition MONITOR_EVENT = new MessageDefinition("rtaware_msgs/msg/MonitorEvent",
            "# An event of the rtaware monitor; times are world time in ns.\n"
                    + "# deadline_miss | expired_read | period_change | task_error\n"
                    + "string kind\n"
                    + "string task\n"
                    + "# the input concerned (expired_read)\n"
                    + "string key\n"
                    + "int64 time_ns\n"
                    + "int64 release_ns\n"
                    + "int64 deadline_ns\n"
                    + "# true if the miss was detected while the cycle was still running\n"
                    + "bool still_running\n"
                    + "int64 age_ns\n"
                    + "int64 max_age_ns\n"
                    + "int64 old_period_ns\n"
                    + "int64 new_period_ns\n"
                    + "# the error, or why the period changed\n"
                    + "string detail\n");

    private TimingTypes() {
    }
}
