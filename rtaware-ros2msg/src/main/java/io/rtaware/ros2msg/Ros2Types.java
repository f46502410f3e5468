package io.rtaware.ros2msg;

/**
 * The ROS 2 message definitions rtaware speaks (Jazzy, comments removed) and the top-level
 * types with their RIHS01 hashes. The hashes are the values ROS 2 computes from these
 * definitions; tests recompute them against an independent implementation's output and with
 * {@link TypeDescriptionHash}.
 */
public final class Ros2Types {

    /** {@code builtin_interfaces/msg/Time}. */
    public static final MessageDefinition TIME = new MessageDefinition("builtin_interfaces/msg/Time",
            "int32 sec\nuint32 nanosec\n");
    /** {@code std_msgs/msg/Header}. */
    public static final MessageDefinition HEADER = new MessageDefinition("std_msgs/msg/Header",
            "builtin_interfaces/Time stamp\nstring frame_id\n", TIME);
    /** {@code geometry_msgs/msg/Vector3}. */
    public static final MessageDefinition VECTOR3 = new MessageDefinition("geometry_msgs/msg/Vector3",
            "float64 x\nfloat64 y\nfloat64 z\n");
    /** {@code geometry_msgs/msg/Point}. */
    public static final MessageDefinition POINT = new MessageDefinition("geometry_msgs/msg/Point",
            "float64 x\nfloat64 y\nfloat64 z\n");
    /** {@code geometry_msgs/msg/Quaternion}. */
    public static final MessageDefinition QUATERNION = new MessageDefinition("geometry_msgs/msg/Quaternion",
            "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n");
    /** {@code geometry_msgs/msg/Pose}. */
    public static final MessageDefinition POSE = new MessageDefinition("geometry_msgs/msg/Pose",
            "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n", POINT, QUATERNION);
    /** {@code geometry_msgs/msg/PoseWithCovariance}. */
    public static final MessageDefinition POSE_WITH_COVARIANCE = new MessageDefinition(
            "geometry_msgs/msg/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n", POSE);
    /** {@code geometry_msgs/msg/Twist}. */
    public static final MessageDefinition TWIST_DEFINITION = new MessageDefinition("geometry_msgs/msg/Twist",
            "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n", VECTOR3);
    /** {@code geometry_msgs/msg/TwistWithCovariance}. */
    public static final MessageDefinition TWIST_WITH_COVARIANCE = new MessageDefinition(
            "geometry_msgs/msg/TwistWithCovariance", "geometry_msgs/Twist twist\nfloat64[36] covariance\n",
            TWIST_DEFINITION);
    /** {@code geometry_msgs/msg/PoseStamped}. */
    public static final MessageDefinition POSE_STAMPED_DEFINITION = new MessageDefinition(
            "geometry_msgs/msg/PoseStamped", "std_msgs/Header header\ngeometry_msgs/Pose pose\n", HEADER, POSE);
    /** {@code nav_msgs/msg/MapMetaData}. */
    public static final MessageDefinition MAP_META_DATA = new MessageDefinition("nav_msgs/msg/MapMetaData",
            "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\n"
                    + "geometry_msgs/Pose origin\n", TIME, POSE);
    /** {@code diagnostic_msgs/msg/KeyValue}. */
    public static final MessageDefinition KEY_VALUE = new MessageDefinition("diagnostic_msgs/msg/KeyValue",
            "string key\nstring value\n");
    /** {@code diagnostic_msgs/msg/DiagnosticStatus}. */
    public static final MessageDefinition DIAGNOSTIC_STATUS = new MessageDefinition(
            "diagnostic_msgs/msg/DiagnosticStatus",
            "byte OK=0\nbyte WARN=1\nbyte ERROR=2\nbyte STALE=3\nbyte level\nstring name\nstring message\n"
                    + "string hardware_id\ndiagnostic_msgs/KeyValue[] values\n", KEY_VALUE);

    /** {@code sensor_msgs/msg/LaserScan}. */
    public static final Ros2MessageType LASER_SCAN = new Ros2MessageType(new MessageDefinition(
            "sensor_msgs/msg/LaserScan",
            "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
                    + "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
                    + "float32[] ranges\nfloat32[] intensities\n", HEADER),
            "RIHS01_64c191398013af96509d518dac71d5164f9382553fce5c1f8cca5be7924bd828");
    /** {@code nav_msgs/msg/Odometry}. */
    public static final Ros2MessageType ODOMETRY = new Ros2MessageType(new MessageDefinition(
            "nav_msgs/msg/Odometry",
            "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
                    + "geometry_msgs/TwistWithCovariance twist\n", HEADER, POSE_WITH_COVARIANCE, TWIST_WITH_COVARIANCE),
            "RIHS01_3cc97dc7fb7502f8714462c526d369e35b603cfc34d946e3f2eda2766dfec6e0");
    /** {@code geometry_msgs/msg/Twist}. */
    public static final Ros2MessageType TWIST = new Ros2MessageType(TWIST_DEFINITION,
            "RIHS01_9c45bf16fe0983d80e3cfe750d6835843d265a9a6c46bd2e609fcddde6fb8d2a");
    /** {@code nav_msgs/msg/Path}. */
    public static final Ros2MessageType PATH = new Ros2MessageType(new MessageDefinition("nav_msgs/msg/Path",
            "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n", HEADER, POSE_STAMPED_DEFINITION),
            "RIHS01_1957a5bb3cee5da65c4e52e52b65a93df227efce4c20f8458b36e73066ca334b");
    /** {@code nav_msgs/msg/OccupancyGrid}. */
    public static final Ros2MessageType OCCUPANCY_GRID = new Ros2MessageType(new MessageDefinition(
            "nav_msgs/msg/OccupancyGrid", "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n",
            HEADER, MAP_META_DATA),
            "RIHS01_8d348150c12913a31ee0ec170fbf25089e4745d17035792a1ba94d6f0bc0cfc7");
    /** {@code geometry_msgs/msg/PoseStamped}. */
    public static final Ros2MessageType POSE_STAMPED = new Ros2MessageType(POSE_STAMPED_DEFINITION,
            "RIHS01_10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232d73b4cd8");
    /** {@code diagnostic_msgs/msg/DiagnosticArray}. */
    public static final Ros2MessageType DIAGNOSTIC_ARRAY = new Ros2MessageType(new MessageDefinition(
            "diagnostic_msgs/msg/DiagnosticArray", "std_msgs/Header header\ndiagnostic_msgs/DiagnosticStatus[] status\n",
            HEADER, DIAGNOSTIC_STATUS),
            "RIHS01_5a8a36efb05fb25070fa0fb3810290c0e6cd4862b54a8fb975a1ee8dc55a333e");

    /** {@code geometry_msgs/msg/Transform}. */
    public static final MessageDefinition TRANSFORM = new MessageDefinition("geometry_msgs/msg/Transform",
            "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n", VECTOR3, QUATERNION);
    /** {@code geometry_msgs/msg/TransformStamped}. */
    public static final MessageDefinition TRANSFORM_STAMPED = new MessageDefinition(
            "geometry_msgs/msg/TransformStamped",
            "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n", HEADER, TRANSFORM);
    /**
     * {@code tf2_msgs/msg/TFMessage}, what {@code /tf} and {@code /tf_static} carry (its hash as
     * rosbags computes it for Jazzy; check_ros2_profile.py checks it against rosbags).
     */
    public static final Ros2MessageType TF_MESSAGE = new Ros2MessageType(new MessageDefinition(
            "tf2_msgs/msg/TFMessage", "geometry_msgs/TransformStamped[] transforms\n", TRANSFORM_STAMPED),
            "RIHS01_e369d0f05a23ae52508854b66f6aa0437f3449d652e8cbf22d5abe85d020f087");

    /**
     * {@code rosgraph_msgs/msg/Clock}, what {@code /clock} carries when a system runs on simulated
     * time (its hash as {@link TypeDescriptionHash} and rosbags compute it for Jazzy).
     */
    public static final Ros2MessageType CLOCK = new Ros2MessageType(new MessageDefinition(
            "rosgraph_msgs/msg/Clock", "builtin_interfaces/Time clock\n", TIME),
            "RIHS01_692f7a66e93a3c83e71765d033b60349ba68023a8c689a79e48078bcb5c58564");

    /** {@code statistics_msgs/msg/StatisticDataPoint}: one statistic of a window (its type, its value). */
    public static final MessageDefinition STATISTIC_DATA_POINT = new MessageDefinition(
            "statistics_msgs/msg/StatisticDataPoint", "uint8 data_type\nfloat64 data\n");
    /**
     * {@code statistics_msgs/msg/MetricsMessage}, what ROS 2's topic statistics publish on
     * {@code /statistics} (its hash as {@link TypeDescriptionHash} and rosbags compute it for Jazzy).
     */
    public static final Ros2MessageType METRICS_MESSAGE = new Ros2MessageType(new MessageDefinition(
            "statistics_msgs/msg/MetricsMessage",
            "string measurement_source_name\nstring metrics_source\nstring unit\n"
                    + "builtin_interfaces/Time window_start\nbuiltin_interfaces/Time window_stop\n"
                    + "statistics_msgs/StatisticDataPoint[] statistics\n", TIME, STATISTIC_DATA_POINT),
            "RIHS01_36a67fb499fc2a11b8b9ff9ac735ed76e8d5a1f7775d6d5b97b625188ec68e20");
    /**
     * {@code rcl_interfaces/msg/Log}, what a ROS 2 node's log lines carry on {@code /rosout} (its
     * Jazzy hash as {@link TypeDescriptionHash} and rosbags compute it; the severity constants as
     * rcl_interfaces defines them).
     */
    public static final Ros2MessageType LOG = new Ros2MessageType(new MessageDefinition(
            "rcl_interfaces/msg/Log",
            "byte DEBUG=10\nbyte INFO=20\nbyte WARN=30\nbyte ERROR=40\nbyte FATAL=50\n"
                    + "builtin_interfaces/Time stamp\nuint8 level\nstring name\nstring msg\nstring file\n"
                    + "string function\nuint32 line\n", TIME),
            "RIHS01_e28ce254ca8abc06abf92773b74602cdbf116ed34fbaf294fb9f81da9f318eac");

    private Ros2Types() {
    }
}
