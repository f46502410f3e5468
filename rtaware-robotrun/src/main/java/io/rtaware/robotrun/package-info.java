/**
 * One run of the paper's navigation controller on a robot, usable from a user's {@code main}
 * without the command line: {@link io.rtaware.robotrun.NavRun} (the entry point) puts the
 * controller and its robot's data task on one monitor, {@link io.rtaware.robotrun.RobotLink}
 * reaches the robot (the built-in simulator over Player, an external Player server, or a ROS 2
 * robot through {@link io.rtaware.robotrun.Ros2Link}), {@link io.rtaware.robotrun.Referee}
 * watches it from outside (ground truth), {@link io.rtaware.robotrun.Supervisor} applies the
 * end-of-run rules (finish, time limit, stuck, lost server, safety fault) into a shared
 * {@link io.rtaware.robotrun.RunState} (and, given a recorder, logs each collision, near miss
 * and the ending on its {@code /rosout}), {@link io.rtaware.robotrun.CourseCheck} warns of a course
 * that cannot work, and {@link io.rtaware.robotrun.RunSection} is the report's account of the run.
 * {@link io.rtaware.robotrun.SimulatorFeed} shows the simulated robot to a recording's tap (the
 * Foxglove server) without a controller.
 */
package io.rtaware.robotrun;
