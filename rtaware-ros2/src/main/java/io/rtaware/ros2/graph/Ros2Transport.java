package io.rtaware.ros2.graph;

/** How a {@link Ros2Context} reaches the ROS graph. */
public enum Ros2Transport {

    /** Zenoh with rmw_zenoh's key expressions, liveliness tokens and attachments. */
    RMW_ZENOH("rmw_zenoh"),
    /**
     * DDS (RTPS), through a ROS 2 DDS bridge ({@code zenoh-plugin-ros2dds}) this process starts: the
     * bridge's keys ({@code scan} for {@code rt/scan}), routes announced to it, no attachments.
     */
    DDS("dds");

    private final String reportName;

    Ros2Transport(String reportName) {
        this.reportName = reportName;
    }

    /** @return the name in reports ({@code rmw_zenoh} or {@code dds}) */
    public String reportName() {
        return reportName;
    }
}
