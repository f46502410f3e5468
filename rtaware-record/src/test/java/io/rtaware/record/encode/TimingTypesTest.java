package io.rtaware.record.encode;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The RIHS01 hashes of the {@code rtaware_msgs} types against an independent implementation:
 * rosbags 0.11.9's {@code hash_rihs01} of the package's {@code .msg} files (registered with
 * {@code get_types_from_msg} in the Jazzy store), computed once and written here;
 * check_ros2_profile.py recomputes them from every recording's schemas in {@code .ci/run}.
 */
class TimingTypesTest {

    @Test
    void rtawareMsgsHashesAreTheOnesRosbagsComputesFromTheMsgFiles() {
        assertEquals("RIHS01_41d82fe833a8285e1585cf94c812b9322faa9d52d226199897a473e27982a76f",
                TimingTypes.TASK_CYCLE.typeHash(), "TaskCycle");
        assertEquals("RIHS01_4a47656b62925287e3b2764a03a2b6d439e8bcb1fd059d58478edbe3139d472b",
                TimingTypes.MONITOR_EVENT.typeHash(), "MonitorEvent");
        assertEquals("RIHS01_7a51306c6dcb3c7e13d8d73edb5ee7608e03f3d80a9823463abed51f290189c0",
                TimingTypes.STATE_JSON.typeHash(), "StateJson");
    }
}
