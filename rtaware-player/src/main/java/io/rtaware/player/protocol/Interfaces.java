package io.rtaware.player.protocol;

/**
 * Player interface codes (the number prefix of each interface definition file) and their
 * names. Constants only; thread-safe.
 */
public final class Interfaces {

    /** The server itself (index 0): device list, subscriptions, data mode. */
    public static final int PLAYER = 1;
    /** Mobile base: odometry and velocity commands. */
    public static final int POSITION2D = 4;
    /** Sonar array (named only). */
    public static final int SONAR = 5;
    /** Planar laser range finder. */
    public static final int LASER = 6;
    /** Simulator access (Stage): ground-truth poses by model name. */
    public static final int SIMULATION = 31;
    /** Occupancy map (named only). */
    public static final int MAP = 42;
    /** Path planner (named only). */
    public static final int PLANNER = 44;
    /** Generic range sensor array; Stage 4 serves its lasers as rangers. */
    public static final int RANGER = 62;

    private Interfaces() {
    }

    /**
     * @param code an interface code
     * @return its name, e.g. {@code laser}, or {@code interface<code>} if unknown
     */
    public static String name(int code) {
        return switch (code) {
            case PLAYER -> "player";
            case POSITION2D -> "position2d";
            case SONAR -> "sonar";
            case LASER -> "laser";
            case SIMULATION -> "simulation";
            case MAP -> "map";
            case PLANNER -> "planner";
            case RANGER -> "ranger";
            default -> "interface" + code;
        };
    }

    /**
     * @param name an interface name, e.g. {@code ranger}
     * @return its code, or -1 if this library does not know the name
     */
    public static int code(String name) {
        return switch (name) {
            case "player" -> PLAYER;
            case "position2d" -> POSITION2D;
            case "sonar" -> SONAR;
            case "laser" -> LASER;
            case "simulation" -> SIMULATION;
            case "map" -> MAP;
            case "planner" -> PLANNER;
            case "ranger" -> RANGER;
            default -> -1;
        };
    }
}
