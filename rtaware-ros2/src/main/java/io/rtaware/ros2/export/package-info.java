/**
 * A running controller seen from another machine: {@link io.rtaware.ros2.export.MonitorExporter}
 * publishes the keys of a monitor that have a ROS 2 type as that type under {@code /rtaware/...},
 * and every task's and key's health once a second as {@code diagnostic_msgs/msg/DiagnosticArray}
 * on {@code /diagnostics}, from a thread of its own, never from a task's thread.
 */
package io.rtaware.ros2.export;
