package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The RIHS01 algorithm against hashes it did not make: those of ROS 2 Jazzy's standard types
 * (in {@link Ros2Types}, checked against rosbags' vectors in {@link ReferenceVectorsTest}) and
 * {@code std_msgs/msg/String}'s as rmw_zenoh's design document shows it in a key expression.
 */
class TypeDescriptionHashTest {

    @Test
    void recomputesTheHashOfEveryStandardType() {
        for (Ros2MessageType type : List.of(Ros2Types.LASER_SCAN, Ros2Types.ODOMETRY, Ros2Types.TWIST, Ros2Types.PATH,
                Ros2Types.OCCUPANCY_GRID, Ros2Types.POSE_STAMPED, Ros2Types.DIAGNOSTIC_ARRAY, Ros2Types.TF_MESSAGE,
                Ros2Types.CLOCK, Ros2Types.METRICS_MESSAGE, Ros2Types.LOG)) {
            assertEquals(type.typeHash(), TypeDescriptionHash.rihs01(type.definition()), type.name());
        }
    }

    @Test
    void recomputesTheHashRmwZenohsDesignDocumentShowsForStdMsgsString() {
        assertEquals("RIHS01_df668c740482bbd48fb39d76a70dfd4bd59db1288021743503259e948f6b1a18",
                TypeDescriptionHash.rihs01(new MessageDefinition("std_msgs/msg/String", "string data\n")));
    }

    @Test
    void theJsonIsPythonsJsonDumpsOfTheDescriptionWithReferencedTypesByName() {
        assertEquals("{\"type_description\": {\"type_name\": \"rosgraph_msgs/msg/Clock\", \"fields\": [{\"name\": "
                + "\"clock\", \"type\": {\"type_id\": 1, \"capacity\": 0, \"string_capacity\": 0, \"nested_type_name\": "
                + "\"builtin_interfaces/msg/Time\"}}]}, \"referenced_type_descriptions\": [{\"type_name\": "
                + "\"builtin_interfaces/msg/Time\", \"fields\": [{\"name\": \"sec\", \"type\": {\"type_id\": 6, "
                + "\"capacity\": 0, \"string_capacity\": 0, \"nested_type_name\": \"\"}}, {\"name\": \"nanosec\", "
                + "\"type\": {\"type_id\": 7, \"capacity\": 0, \"string_capacity\": 0, \"nested_type_name\": \"\"}}]}]}",
                TypeDescriptionHash.canonicalJson(Ros2Types.CLOCK.definition()));
    }

    @Test
    void commentsConstantsAndDefaultValuesDoNotChangeTheHash() {
        String plain = TypeDescriptionHash.rihs01(new MessageDefinition("a_msgs/msg/A", "int32 x\nstring name\n"));
        assertEquals(plain, TypeDescriptionHash.rihs01(new MessageDefinition("a_msgs/msg/A",
                "# a comment\nint32 LIMIT=3\nint32 x 7  # with a default\n\nstring name\nstring GREETING = \"hi\"\n")));
        assertNotEquals(plain, TypeDescriptionHash.rihs01(new MessageDefinition("a_msgs/msg/A", "int64 x\nstring name\n")),
                "a field's type is part of the hash");
    }

    @Test
    void arraysSequencesAndBoundedStringsHaveTheirTypeIdsAndCapacities() {
        String json = TypeDescriptionHash.canonicalJson(new MessageDefinition("a_msgs/msg/A",
                "float64[36] c\nint8[] d\nuint16[<=5] e\nstring<=10 f\nstring<=4[<=3] g\nbool h\nbyte i\nB[] j\n",
                new MessageDefinition("a_msgs/msg/B", "")));
        assertTrue(json.contains("\"name\": \"c\", \"type\": {\"type_id\": 59, \"capacity\": 36"), json);
        assertTrue(json.contains("\"name\": \"d\", \"type\": {\"type_id\": 146, \"capacity\": 0"), json);
        assertTrue(json.contains("\"name\": \"e\", \"type\": {\"type_id\": 101, \"capacity\": 5"), json);
        assertTrue(json.contains("\"name\": \"f\", \"type\": {\"type_id\": 21, \"capacity\": 0, \"string_capacity\": 10"),
                json);
        assertTrue(json.contains("\"name\": \"g\", \"type\": {\"type_id\": 117, \"capacity\": 3, \"string_capacity\": 4"),
                json);
        assertTrue(json.contains("\"name\": \"h\", \"type\": {\"type_id\": 15,"), json);
        assertTrue(json.contains("\"name\": \"i\", \"type\": {\"type_id\": 16,"), json);
        assertTrue(json.contains("\"name\": \"j\", \"type\": {\"type_id\": 145, \"capacity\": 0, \"string_capacity\": 0, "
                + "\"nested_type_name\": \"a_msgs/msg/B\"}"), json);
        assertTrue(json.endsWith("[{\"type_name\": \"a_msgs/msg/B\", \"fields\": [{\"name\": "
                + "\"structure_needs_at_least_one_member\", \"type\": {\"type_id\": 3, \"capacity\": 0, "
                + "\"string_capacity\": 0, \"nested_type_name\": \"\"}}]}]}"), "an empty type gets rosidl's placeholder: "
                + json);
    }

    @Test
    void aNestedTypeWithoutItsDefinitionIsRefusedByName() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> TypeDescriptionHash.rihs01(new MessageDefinition("a_msgs/msg/A", "std_msgs/Header header\n")));
        assertEquals("a_msgs/msg/A uses std_msgs/msg/Header, whose definition was not given", e.getMessage());
    }
}
