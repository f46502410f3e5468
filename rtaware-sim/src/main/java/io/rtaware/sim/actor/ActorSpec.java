package io.rtaware.sim.actor;

import io.rtaware.robot.geometry.Point2d;
import java.util.List;
import java.util.Locale;
import java.util.Objects;

/**
 * One actor of a scenario, as its {@code actors:} entry says. Immutable and validated.
 *
 * <ul>
 *   <li>a {@link Kind#BODY} (a person, a cart) moves along {@code path} at {@code speedMps},
 *       {@link Repeat#ONCE}, in a {@link Repeat#LOOP} (back to the first point and round again)
 *       or {@link Repeat#BACK_AND_FORTH}; it waits at the first point until {@code startAtS}
 *       (plus a per-run draw from {@code [0, startJitterS)}) or, with {@code startWithinM}
 *       above 0, until the robot's centre comes within that distance of it;</li>
 *   <li>a {@link Kind#DOOR} is open (absent) until {@code appearAtS}, then closed: its box
 *       stands at {@code path.get(0)};</li>
 *   <li>an {@link Kind#OBSTACLE} appears at {@code path.get(0)} at {@code appearAtS}.</li>
 * </ul>
 *
 * @param name the actor's name (unique in its scenario; also its Player simulation model name)
 * @param kind body, door or obstacle
 * @param shape its outline
 * @param path where it goes: at least one point; a body that moves needs two
 * @param speedMps speed along the path, m/s, 0 to {@link #MAX_SPEED_MPS} (0 for doors and obstacles)
 * @param repeat what a body does at the end of its path
 * @param startAtS world seconds from the start at which a body starts moving, not negative
 * @param startWithinM if above 0, a body starts when the robot comes this near instead, metres
 * @param startJitterS a body's start is delayed by a per-run draw from [0, this), seconds
 * @param appearAtS world seconds from which the actor is there (a door closes, an obstacle appears)
 */
public record ActorSpec(String name, Kind kind, ActorShape shape, List<Point2d> path, double speedMps,
                        Repeat repeat, double startAtS, double startWithinM, double startJitterS, double appearAtS) {

    /**
     * The fastest an actor may move, m/s: faster than anything that shares a floor with a mobile
     * robot (a sprinting person, about 10 m/s); a speed above it is a slip (a unit, an exponent),
     * and the simulator's steps and the laser's sweep are not made for it.
     */
    public static final double MAX_SPEED_MPS = 10.0;

    /** What kind of actor. */
    public enum Kind {
        /** Moves along its path. */
        BODY,
        /** Closes (appears) at a time. */
        DOOR,
        /** Appears at a time. */
        OBSTACLE;

        /** @return the name in scenario files */
        public String yamlName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /** What a body does at the end of its path. */
    public enum Repeat {
        /** Stops at the last point. */
        ONCE,
        /** Goes on from the last point to the first, and round again. */
        LOOP,
        /** Turns back at each end. */
        BACK_AND_FORTH;

        /** @return the name in scenario files */
        public String yamlName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * @param name the actor's name, not null
     * @param kind body, door or obstacle
     * @param shape its outline
     * @param path where it goes: at least one point; a body that moves needs two
     * @param speedMps speed along the path, m/s, not negative
     * @param repeat what a body does at the end of its path
     * @param startAtS world seconds from the start at which a body starts moving, not negative
     * @param startWithinM if above 0, a body starts when the robot comes this near instead, metres
     * @param startJitterS a body's start is delayed by a per-run draw from [0, this), seconds
     * @param appearAtS world seconds from which the actor is there
     * @throws IllegalArgumentException naming the field and the value if one is out of range
     */
    public ActorSpec {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(shape, "shape");
        Objects.requireNonNull(repeat, "repeat");
        path = List.copyOf(path);
        if (name.isBlank()) {
            throw new IllegalArgumentException("name must not be empty, got '" + name + "'");
        }
        if (path.isEmpty()) {
            throw new IllegalArgumentException("path must have at least one point, got []");
        }
        for (Point2d p : path) {
            if (!Double.isFinite(p.xM()) || !Double.isFinite(p.yM())) {
                throw new IllegalArgumentException("path points must be finite, got " + p);
            }
        }
        notNegative("speed_mps", speedMps);
        if (speedMps > MAX_SPEED_MPS) {
            throw new IllegalArgumentException("speed_mps must be at most " + MAX_SPEED_MPS + " m/s, got " + speedMps);
        }
        notNegative("start_at_s", startAtS);
        notNegative("start_when_robot_within_m", startWithinM);
        notNegative("start_jitter_s", startJitterS);
        notNegative("appear_at_s", appearAtS);
        if (kind == Kind.BODY && path.size() > 1 && speedMps == 0) {
            throw new IllegalArgumentException("speed_mps must be positive for a body with a path, got " + speedMps);
        }
    }

    private static void notNegative(String field, double value) {
        if (!(value >= 0) || Double.isInfinite(value)) {
            throw new IllegalArgumentException(field + " must be finite and not negative, got " + value);
        }
    }

    /** @return the length of one pass of the path in metres (for a loop, with the way back to the start) */
    public double passLengthM() {
        double length = 0;
        for (int i = 1; i < path.size(); i++) {
            length += path.get(i - 1).distanceTo(path.get(i));
        }
        if (repeat == Repeat.LOOP && path.size() > 1) {
            length += path.get(path.size() - 1).distanceTo(path.get(0));
        }
        return length;
    }

    /** @return true for a body that moves */
    public boolean moves() {
        return kind == Kind.BODY && path.size() > 1 && speedMps > 0;
    }
}
