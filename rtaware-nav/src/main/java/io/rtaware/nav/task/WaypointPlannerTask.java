package io.rtaware.nav.task;

import io.rtaware.core.data.Input;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.Output;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.nav.logic.PathFollower;
import io.rtaware.nav.logic.WaypointSequencer;
import io.rtaware.robot.msg.CourseStatus;
import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.MotionRequest;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.PlannedPath;
import io.rtaware.robot.msg.RobotKeys;
import java.time.Duration;

/**
 * WaypointPlanner ({@code waypoint}): holds the course, requests the current waypoint as a goal
 * on its goal key (and removes it once reached, by publishing the next one instead), follows
 * the planner's {@code path} to it by pure pursuit, and publishes its motion request on
 * {@code motion.waypoint} and its progress on {@code course}. Until a path to the current
 * waypoint arrives (or when the planner finds none) it heads straight for the waypoint and
 * leaves obstacles to the avoider. With no fresh pose, or once the course is done, it requests
 * nothing, and the mediator stops the robot. If given a waypoint input key, a new value there
 * replaces the course and restarts it.
 *
 * <p>Run by one thread at a time; {@link #progress()} is thread-safe.
 */
public final class WaypointPlannerTask implements Task {

    private final Key<GoalSet> goalsKey;
    private final Key<PlannedPath> pathKey;
    private final Key<CourseStatus> courseKey;
    private final Key<GoalSet> waypointsInKey;
    private final GoalSet initialCourse;
    private final WaypointSequencer sequencer;
    private final PathFollower follower;
    private final long odometryMaxAgeNs;
    private Input<Odometry> odometry;
    private Input<PlannedPath> path;
    private Input<GoalSet> waypointsIn;
    private Output<GoalSet> goals;
    private Output<MotionRequest> motion;
    private Output<CourseStatus> course;
    private long publishedGoalId = -1;

    private volatile int reached;
    private volatile int total;
    private volatile boolean done;
    private volatile double distanceToGoalM = Double.NaN;
    private volatile double distanceToFinishM = Double.NaN;

    /**
     * @param goalsKey this requester's goal request key
     * @param pathKey the planner's path key
     * @param courseKey the course status key to publish on
     * @param waypointsInKey the course input key, or null if the course is fixed
     * @param initialCourse the course to start with (copied)
     * @param sequencer the course logic, with the capacity of the course
     * @param follower the path-following logic
     * @param odometryMaxAgeNs oldest pose trusted, in world ns
     */
    public WaypointPlannerTask(Key<GoalSet> goalsKey, Key<PlannedPath> pathKey, Key<CourseStatus> courseKey,
                               Key<GoalSet> waypointsInKey, GoalSet initialCourse, WaypointSequencer sequencer,
                               PathFollower follower, long odometryMaxAgeNs) {
        this.goalsKey = goalsKey;
        this.pathKey = pathKey;
        this.courseKey = courseKey;
        this.waypointsInKey = waypointsInKey;
        this.initialCourse = new GoalSet(initialCourse.capacity());
        this.initialCourse.copyFrom(initialCourse);
        this.sequencer = sequencer;
        this.follower = follower;
        this.odometryMaxAgeNs = odometryMaxAgeNs;
    }

    @Override
    public void initialize(TaskSetup setup) {
        odometry = setup.consume(RobotKeys.ODOMETRY, Duration.ofNanos(odometryMaxAgeNs));
        path = setup.consume(pathKey);
        if (waypointsInKey != null) {
            waypointsIn = setup.consume(waypointsInKey);
        }
        goals = setup.produce(goalsKey);
        motion = setup.produce(RobotKeys.MOTION_WAYPOINT);
        course = setup.produce(courseKey);
        sequencer.setWaypoints(initialCourse);
        total = sequencer.count();
    }

    @Override
    public void execute(long nowNs) {
        if (waypointsIn != null && waypointsIn.isNew()) {
            sequencer.setWaypoints(waypointsIn.value());
        }
        boolean poseKnown = odometry.hasValue() && !odometry.isExpired();
        Odometry pose = odometry.value();
        if (poseKnown) {
            sequencer.update(pose.xM, pose.yM);
        }
        publishGoal();
        MotionRequest request = motion.value();
        if (!poseKnown || sequencer.isDone()) {
            request.release();
        } else {
            PlannedPath p = path.value();
            if (p.valid && p.count() > 0 && p.goalId == sequencer.currentGoalId()
                    && p.goalXM == sequencer.currentXM() && p.goalYM == sequencer.currentYM()) {
                follower.follow(pose.xM, pose.yM, pose.yawRad, p.xM, p.yM, p.count(), request);
            } else {
                follower.driveTo(pose.xM, pose.yM, pose.yawRad, sequencer.currentXM(), sequencer.currentYM(), request);
            }
        }
        motion.publish();
        publishCourse(poseKnown, pose);
    }

    private void publishGoal() {
        long wanted = sequencer.isDone() ? 0 : sequencer.currentGoalId();
        if (wanted == publishedGoalId) {
            return;
        }
        GoalSet g = goals.value();
        g.clear();
        if (!sequencer.isDone()) {
            g.add(wanted, sequencer.currentXM(), sequencer.currentYM());
        }
        goals.publish();
        publishedGoalId = wanted;
    }

    private void publishCourse(boolean poseKnown, Odometry pose) {
        CourseStatus s = course.value();
        s.waypointsReached = sequencer.reached();
        s.waypointsTotal = sequencer.count();
        s.currentIndex = sequencer.index();
        s.done = sequencer.isDone();
        s.goalXM = sequencer.currentXM();
        s.goalYM = sequencer.currentYM();
        s.positionKnown = poseKnown;
        if (poseKnown) {
            s.distanceToGoalM = s.done ? 0 : Math.hypot(s.goalXM - pose.xM, s.goalYM - pose.yM);
            s.distanceToFinishM = sequencer.distanceToFinishM(pose.xM, pose.yM);
        }
        course.publish();
        reached = s.waypointsReached;
        total = s.waypointsTotal;
        done = s.done;
        distanceToGoalM = poseKnown ? s.distanceToGoalM : Double.NaN;
        distanceToFinishM = poseKnown ? s.distanceToFinishM : Double.NaN;
    }

    /**
     * Progress as of the last cycle; each field is current but they may come from consecutive
     * cycles. Thread-safe; allocates the returned record.
     *
     * @return the progress
     */
    public CourseProgress progress() {
        return new CourseProgress(reached, total, done, distanceToGoalM, distanceToFinishM);
    }

    /**
     * A snapshot of course progress, for status lines and run reports.
     *
     * @param waypointsReached waypoints reached so far
     * @param waypointsTotal waypoints in the course
     * @param done true once the finish was reached
     * @param distanceToGoalM distance to the current waypoint in metres (NaN while the pose is
     *     unknown)
     * @param distanceToFinishM distance to the finish in metres (NaN while the pose is unknown)
     */
    public record CourseProgress(int waypointsReached, int waypointsTotal, boolean done,
                                 double distanceToGoalM, double distanceToFinishM) {
    }
}
