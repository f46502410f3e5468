package io.rtaware.player.protocol;

/**
 * Message subtypes of the interfaces this library speaks, named as in Player's interface
 * definitions ({@code <INTERFACE>_<TYPE>_<NAME>}), plus the access, data-mode and
 * replace-rule codes that appear in bodies. Constants only; thread-safe.
 */
public final class Subtypes {

    /** player REQ: list the server's devices. */
    public static final int PLAYER_REQ_DEVLIST = 1;
    /** player REQ: driver name of one device. */
    public static final int PLAYER_REQ_DRIVERINFO = 2;
    /** player REQ: subscribe to or unsubscribe from a device. */
    public static final int PLAYER_REQ_DEV = 3;
    /** player REQ: PULL mode, send one round of data. */
    public static final int PLAYER_REQ_DATA = 4;
    /** player REQ: choose PUSH or PULL. */
    public static final int PLAYER_REQ_DATAMODE = 5;
    /** player REQ: add a queue replace rule. */
    public static final int PLAYER_REQ_ADD_REPLACE_RULE = 10;
    /** player SYNCH: end of a PULL round. */
    public static final int PLAYER_SYNCH_OK = 1;
    /** player SYNCH: end of a PULL round, messages were dropped (body: u32 count). */
    public static final int PLAYER_SYNCH_OVERFLOW = 2;

    /** position2d DATA: pose, velocity, stall. */
    public static final int POSITION2D_DATA_STATE = 1;
    /** position2d CMD: velocity. */
    public static final int POSITION2D_CMD_VEL = 1;
    /** position2d REQ: geometry (reply 72 bytes). */
    public static final int POSITION2D_REQ_GET_GEOM = 1;
    /** position2d REQ: motors on/off. */
    public static final int POSITION2D_REQ_MOTOR_POWER = 2;

    /** laser DATA: one scan. */
    public static final int LASER_DATA_SCAN = 1;
    /** laser REQ: geometry. */
    public static final int LASER_REQ_GET_GEOM = 1;
    /** laser REQ: scan configuration. */
    public static final int LASER_REQ_GET_CONFIG = 3;

    /** ranger DATA: ranges (doubles). */
    public static final int RANGER_DATA_RANGE = 1;
    /** ranger DATA: intensities (doubles). */
    public static final int RANGER_DATA_INTNS = 3;
    /** ranger REQ: geometry. */
    public static final int RANGER_REQ_GET_GEOM = 1;
    /** ranger REQ: configuration. */
    public static final int RANGER_REQ_GET_CONFIG = 5;

    /** simulation REQ: get a model's 2D pose by name. */
    public static final int SIMULATION_REQ_GET_POSE2D = 1;
    /** simulation REQ: set a model's 2D pose by name. */
    public static final int SIMULATION_REQ_SET_POSE2D = 2;

    /** Access code: subscribe. */
    public static final int ACCESS_OPEN = 1;
    /** Access code: unsubscribe. */
    public static final int ACCESS_CLOSE = 2;
    /** Access code in replies: the (un)subscription failed. */
    public static final int ACCESS_ERROR = 3;

    /** Data mode: the server sends data as soon as it is published. */
    public static final int DATAMODE_PUSH = 1;
    /** Data mode: the server sends data only when asked ({@link #PLAYER_REQ_DATA}). */
    public static final int DATAMODE_PULL = 2;

    /** Replace rule action: queue every message. */
    public static final int REPLACE_ACCEPT = 0;
    /** Replace rule action: keep only the newest message per device, type and subtype. */
    public static final int REPLACE_REPLACE = 1;
    /** Replace rule action: drop matching messages. */
    public static final int REPLACE_IGNORE = 2;

    private Subtypes() {
    }

    /**
     * @param access an access code
     * @return {@code OPEN}, {@code CLOSE}, {@code ERROR} or {@code access<code>}
     */
    public static String accessName(int access) {
        return switch (access) {
            case ACCESS_OPEN -> "OPEN";
            case ACCESS_CLOSE -> "CLOSE";
            case ACCESS_ERROR -> "ERROR";
            default -> "access" + access;
        };
    }
}
