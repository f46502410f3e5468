package io.rtaware.ros2.task;

import io.rtaware.ros2.graph.Ros2Context;
import io.rtaware.ros2.graph.Ros2Names;

/**
 * Where a ROS 2 robot's data is: domain, namespace and topic names, validated on construction.
 * Relative topic names are resolved under the namespace. Immutable.
 *
 * @param domain the ROS domain id
 * @param namespace the robot's namespace ({@code /} for none)
 * @param scan the LaserScan topic
 * @param odom the Odometry topic
 * @param cmdVel the Twist topic the robot obeys
 */
public record Ros2Topics(int domain, String namespace, String scan, String odom, String cmdVel) {

    /**
      * @param domain the ROS domain id
      * @param namespace the robot's namespace ({@code /} for none)
      * @param scan the LaserScan topic
      * @param odom the Odometry topic
      * @param cmdVel the Twist topic the robot obeys
     * @throws IllegalArgumentException naming the invalid name or domain
      */
    public Ros2Topics {
        Ros2Context.checkDomain(domain);
        namespace = Ros2Names.namespace(namespace);
        Ros2Names.resolveTopic(namespace, scan);
        Ros2Names.resolveTopic(namespace, odom);
        Ros2Names.resolveTopic(namespace, cmdVel);
    }

    /** @return the fully qualified scan topic: {@link #scan()} resolved under the namespace */
    public String qualifiedScan() {
        return Ros2Names.resolveTopic(namespace, scan);
    }

    /** @return the fully qualified odometry topic: {@link #odom()} resolved under the namespace */
    public String qualifiedOdom() {
        return Ros2Names.resolveTopic(namespace, odom);
    }

    /** @return the fully qualified Twist topic: {@link #cmdVel()} resolved under the namespace */
    public String qualifiedCmdVel() {
        return Ros2Names.resolveTopic(namespace, cmdVel);
    }

    /** @return domain 0, no namespace, {@code scan}, {@code odom}, {@code cmd_vel} */
    public static Ros2Topics defaults() {
        return new Ros2Topics(0, "/", "scan", "odom", "cmd_vel");
    }
}
