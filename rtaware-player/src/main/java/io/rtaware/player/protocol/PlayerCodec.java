package io.rtaware.player.protocol;

import io.rtaware.player.xdr.PlayerProtocolException;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.msg.Odometry;
import java.util.ArrayList;
import java.util.List;

/**
 * Encoders and decoders of the message bodies this library supports, for both directions
 * (a client writes requests and reads replies and data; a server does the opposite with the
 * same methods). Layouts follow Player's interface definitions as encoded by its XDR
 * generator: every 8- and 16-bit field takes 4 bytes and every variable array is preceded by
 * the struct's own count and then the XDR array count again. Decoders check both counts, every
 * length against the bytes present and the buffer capacity, and that the body holds nothing
 * more. Stateless; thread-safe.
 *
 * <p>To write a message: {@link #beginMessage}, one {@code write...} body method (or none),
 * {@link #endMessage}, which fills in the header's size.
 */
public final class PlayerCodec {

    /** Most devices a DEVLIST reply may list ({@code PLAYER_MAX_DEVICES}). */
    public static final int MAX_DEVICES = 256;
    /** Longest driver name accepted, in bytes ({@code PLAYER_MAX_DRIVER_STRING_LEN}). */
    public static final int MAX_DRIVER_NAME_BYTES = 64;
    /** Longest simulation model name accepted, in bytes. */
    public static final int MAX_MODEL_NAME_BYTES = 1024;
    /** Most element poses or sizes in a ranger GET_GEOM reply. */
    public static final int MAX_RANGER_ELEMENTS = 4096;

    private static final int POSE3D_BYTES = 48;
    private static final int BBOX3D_BYTES = 24;

    private PlayerCodec() {
    }

    // ---------------------------------------------------------------- header

    /**
     * Writes a header with size 0; {@link #endMessage} patches the size.
     *
     * @param w destination
     * @param device address (host and robot as given)
     * @param type message type
     * @param subtype subtype
     * @param timestampS header timestamp in seconds
     * @return the header's position in {@code w}, for {@link #endMessage}
     */
    public static int beginMessage(XdrWriter w, DeviceAddress device, int type, int subtype, double timestampS) {
        int at = w.size();
        w.writeInt(device.host()).writeInt(device.robot()).writeInt(device.interf()).writeInt(device.index())
                .writeInt(type).writeInt(subtype).writeDouble(timestampS).writeInt(0).writeInt(0);
        return at;
    }

    /**
     * Sets the size field of the message begun at {@code headerAt} to the bytes written since.
     *
     * @param w the writer
     * @param headerAt the value {@link #beginMessage} returned
     * @return the body size in bytes
     */
    public static int endMessage(XdrWriter w, int headerAt) {
        int size = w.size() - headerAt - PlayerHeader.SIZE_BYTES;
        w.putInt(headerAt + PlayerHeader.SIZE_FIELD_OFFSET, size);
        return size;
    }

    // ---------------------------------------------------------------- common structs

    /**
     * @param w destination
     * @param a the address (16 bytes)
     */
    public static void writeAddress(XdrWriter w, DeviceAddress a) {
        w.writeInt(a.host()).writeInt(a.robot()).writeInt(a.interf()).writeInt(a.index());
    }

    /**
     * @param r source
     * @param field field name for errors
     * @return the address
     * @throws PlayerProtocolException if truncated
     */
    public static DeviceAddress readAddress(XdrReader r, String field) throws PlayerProtocolException {
        return new DeviceAddress(r.readUnsignedInt(field), r.readUnsignedInt(field), r.readU16(field),
                r.readU16(field));
    }

    private static void writePose3d(XdrWriter w, Pose3d p) {
        w.writeDouble(p.xM()).writeDouble(p.yM()).writeDouble(p.zM()).writeDouble(p.rollRad())
                .writeDouble(p.pitchRad()).writeDouble(p.yawRad());
    }

    private static Pose3d readPose3d(XdrReader r, String field) throws PlayerProtocolException {
        return new Pose3d(r.readDouble(field), r.readDouble(field), r.readDouble(field), r.readDouble(field),
                r.readDouble(field), r.readDouble(field));
    }

    private static void writeBbox3d(XdrWriter w, Bbox3d b) {
        w.writeDouble(b.widthM()).writeDouble(b.lengthM()).writeDouble(b.heightM());
    }

    private static Bbox3d readBbox3d(XdrReader r, String field) throws PlayerProtocolException {
        return new Bbox3d(r.readDouble(field), r.readDouble(field), r.readDouble(field));
    }

    /** Reads a struct count and the XDR array count after it; they must agree. */
    private static int readArrayCounts(XdrReader r, String field, int elementBytes, int max)
            throws PlayerProtocolException {
        int declared = r.readCount(field + "_count", elementBytes, max);
        long at = r.streamPosition();
        int count = r.readCount(field, elementBytes, max);
        if (count != declared) {
            throw new PlayerProtocolException(at, field, "array count " + count + " differs from "
                    + field + "_count " + declared);
        }
        return count;
    }

    /** Reads a counted string: struct count, then xdr_bytes of at most that many bytes. */
    private static String readCountedString(XdrReader r, String field, int maxBytes) throws PlayerProtocolException {
        int declared = r.readCount(field + "_count", 1, maxBytes);
        long at = r.streamPosition();
        int before = r.remaining();
        String s = r.readString(field, maxBytes);
        int length = before - r.remaining() - 4;
        if (XdrReader.padded(declared) != length) {
            throw new PlayerProtocolException(at, field, "byte length differs from " + field + "_count " + declared);
        }
        return s;
    }

    // ---------------------------------------------------------------- player interface

    /**
     * player REQ DATAMODE body.
     *
     * @param w destination
     * @param mode {@link Subtypes#DATAMODE_PUSH} or {@link Subtypes#DATAMODE_PULL}
     */
    public static void writeDataMode(XdrWriter w, int mode) {
        w.writeInt(mode);
    }

    /**
     * @param r source
     * @return the requested data mode
     * @throws PlayerProtocolException if malformed
     */
    public static int readDataMode(XdrReader r) throws PlayerProtocolException {
        int mode = r.readU8("datamode.mode");
        r.expectEnd("datamode");
        return mode;
    }

    /**
     * player REQ ADD_REPLACE_RULE body.
     *
     * @param w destination
     * @param rule the rule
     */
    public static void writeReplaceRule(XdrWriter w, ReplaceRule rule) {
        w.writeInt(rule.interf()).writeInt(rule.index()).writeInt(rule.type()).writeInt(rule.subtype())
                .writeInt(rule.replace());
    }

    /**
     * @param r source
     * @return the rule
     * @throws PlayerProtocolException if malformed
     */
    public static ReplaceRule readReplaceRule(XdrReader r) throws PlayerProtocolException {
        ReplaceRule rule = new ReplaceRule(r.readInt("replace_rule.interf"), r.readInt("replace_rule.index"),
                r.readInt("replace_rule.type"), r.readInt("replace_rule.subtype"), r.readInt("replace_rule.replace"));
        r.expectEnd("replace_rule");
        return rule;
    }

    /**
     * player RESP_ACK DEVLIST body (the request body is empty).
     *
     * @param w destination
     * @param devices the server's devices
     */
    public static void writeDeviceList(XdrWriter w, List<DeviceAddress> devices) {
        w.writeInt(devices.size()).writeInt(devices.size());
        for (DeviceAddress a : devices) {
            writeAddress(w, a);
        }
    }

    /**
     * Decodes a DEVLIST body; an empty body (what clients send) gives an empty list.
     *
     * @param r source
     * @return the devices
     * @throws PlayerProtocolException if malformed
     */
    public static List<DeviceAddress> readDeviceList(XdrReader r) throws PlayerProtocolException {
        if (r.remaining() == 0) {
            return List.of();
        }
        int n = readArrayCounts(r, "devlist.devices", DeviceAddress.SIZE_BYTES, MAX_DEVICES);
        List<DeviceAddress> list = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            list.add(readAddress(r, "devlist.devices"));
        }
        r.expectEnd("devlist");
        return List.copyOf(list);
    }

    /**
     * player REQ DRIVERINFO body (request: empty name) or its reply.
     *
     * @param w destination
     * @param info address and driver name
     */
    public static void writeDriverInfo(XdrWriter w, DriverInfo info) {
        writeAddress(w, info.device());
        w.writeCountedString(info.driverName());
    }

    /**
     * @param r source
     * @return address and driver name
     * @throws PlayerProtocolException if malformed
     */
    public static DriverInfo readDriverInfo(XdrReader r) throws PlayerProtocolException {
        DeviceAddress a = readAddress(r, "driverinfo.addr");
        String name = readCountedString(r, "driverinfo.driver_name", MAX_DRIVER_NAME_BYTES);
        r.expectEnd("driverinfo");
        return new DriverInfo(a, name);
    }

    /**
     * player REQ DEV body, of requests, ACKs and NACKs alike.
     *
     * @param w destination
     * @param req device, access, driver name
     */
    public static void writeDeviceRequest(XdrWriter w, DeviceRequest req) {
        writeAddress(w, req.device());
        w.writeInt(req.access());
        w.writeCountedString(req.driverName());
    }

    /**
     * @param r source
     * @return device, access, driver name
     * @throws PlayerProtocolException if malformed
     */
    public static DeviceRequest readDeviceRequest(XdrReader r) throws PlayerProtocolException {
        DeviceAddress a = readAddress(r, "dev.addr");
        int access = r.readU8("dev.access");
        String name = readCountedString(r, "dev.driver_name", MAX_DRIVER_NAME_BYTES);
        r.expectEnd("dev");
        return new DeviceRequest(a, access, name);
    }

    /**
     * player SYNCH OVERFLOW body (SYNCH OK has none).
     *
     * @param w destination
     * @param dropped dropped message count
     */
    public static void writeSynchOverflow(XdrWriter w, long dropped) {
        w.writeInt(dropped);
    }

    /**
     * Decodes a SYNCH body: empty for OK, a u32 for OVERFLOW (Player sends a bool there, so
     * the value may be garbage; it is only informative).
     *
     * @param r source
     * @return the dropped count, 0 for an empty body
     * @throws PlayerProtocolException if malformed
     */
    public static long readSynch(XdrReader r) throws PlayerProtocolException {
        long dropped = r.remaining() == 0 ? 0 : r.readUnsignedInt("synch.dropped");
        r.expectEnd("synch");
        return dropped;
    }

    // ---------------------------------------------------------------- position2d

    /**
     * position2d DATA STATE body (52 bytes) from an odometry buffer.
     *
     * @param w destination
     * @param o pose, velocity, stall
     */
    public static void writePosition2dState(XdrWriter w, Odometry o) {
        w.writeDouble(o.xM).writeDouble(o.yM).writeDouble(o.yawRad).writeDouble(o.vxMps).writeDouble(o.vyMps)
                .writeDouble(o.omegaRadPerSec).writeInt(o.stall ? 1 : 0);
    }

    /**
     * Decodes position2d DATA STATE into an odometry buffer without allocating.
     *
     * @param r source
     * @param out destination; {@code serverTimeS} is left to the caller
     * @throws PlayerProtocolException if malformed
     */
    public static void readPosition2dState(XdrReader r, Odometry out) throws PlayerProtocolException {
        double x = r.readDouble("position2d.pos.px");
        double y = r.readDouble("position2d.pos.py");
        double yaw = r.readDouble("position2d.pos.pa");
        double vx = r.readDouble("position2d.vel.px");
        double vy = r.readDouble("position2d.vel.py");
        double va = r.readDouble("position2d.vel.pa");
        int stall = r.readU8("position2d.stall");
        r.expectEnd("position2d.state");
        out.xM = x;
        out.yM = y;
        out.yawRad = yaw;
        out.vxMps = vx;
        out.vyMps = vy;
        out.omegaRadPerSec = va;
        out.stall = stall != 0;
    }

    /**
     * position2d CMD VEL body (28 bytes).
     *
     * @param w destination
     * @param vxMps forward speed
     * @param vyMps sideways speed
     * @param omegaRadPerSec turn rate
     * @param state motor state (1 on)
     */
    public static void writeVelocityCmd(XdrWriter w, double vxMps, double vyMps, double omegaRadPerSec, int state) {
        w.writeDouble(vxMps).writeDouble(vyMps).writeDouble(omegaRadPerSec).writeInt(state);
    }

    /**
     * @param r source
     * @return the command
     * @throws PlayerProtocolException if malformed
     */
    public static VelocityCmd readVelocityCmd(XdrReader r) throws PlayerProtocolException {
        VelocityCmd c = new VelocityCmd(r.readDouble("cmd_vel.vel.px"), r.readDouble("cmd_vel.vel.py"),
                r.readDouble("cmd_vel.vel.pa"), r.readU8("cmd_vel.state"));
        r.expectEnd("cmd_vel");
        return c;
    }

    /**
     * position2d REQ MOTOR_POWER body.
     *
     * @param w destination
     * @param on true to enable the motors
     */
    public static void writeMotorPower(XdrWriter w, boolean on) {
        w.writeInt(on ? 1 : 0);
    }

    /**
     * @param r source
     * @return true if the motors are to be enabled
     * @throws PlayerProtocolException if malformed
     */
    public static boolean readMotorPower(XdrReader r) throws PlayerProtocolException {
        int state = r.readU8("motor_power.state");
        r.expectEnd("motor_power");
        return state != 0;
    }

    /**
     * GET_GEOM reply body of position2d or laser (72 bytes).
     *
     * @param w destination
     * @param g pose and size
     */
    public static void writeGeometry(XdrWriter w, Geometry g) {
        writePose3d(w, g.pose());
        writeBbox3d(w, g.size());
    }

    /**
     * @param r source
     * @return pose and size
     * @throws PlayerProtocolException if malformed
     */
    public static Geometry readGeometry(XdrReader r) throws PlayerProtocolException {
        Geometry g = new Geometry(readPose3d(r, "geom.pose"), readBbox3d(r, "geom.size"));
        r.expectEnd("geom");
        return g;
    }

    // ---------------------------------------------------------------- laser

    /**
     * laser DATA SCAN body.
     *
     * @param w destination
     * @param d the scan; {@code intensityCount} 0 writes a scan without intensities
     */
    public static void writeLaserScan(XdrWriter w, LaserData d) {
        w.writeFloat(d.minAngleRad).writeFloat(d.maxAngleRad).writeFloat(d.resolutionRad).writeFloat(d.maxRangeM);
        w.writeInt(d.rangeCount).writeInt(d.rangeCount);
        for (int i = 0; i < d.rangeCount; i++) {
            w.writeFloat(d.rangesM[i]);
        }
        w.writeInt(d.intensityCount);
        w.writeBytes(d.intensities, 0, d.intensityCount);
        w.writeInt(d.id);
    }

    /**
     * Decodes laser DATA SCAN into reusable arrays without allocating.
     *
     * @param r source
     * @param out destination
     * @throws PlayerProtocolException if malformed or larger than {@code out}'s capacity
     */
    public static void readLaserScan(XdrReader r, LaserData out) throws PlayerProtocolException {
        out.minAngleRad = r.readFloat("laser.min_angle");
        out.maxAngleRad = r.readFloat("laser.max_angle");
        out.resolutionRad = r.readFloat("laser.resolution");
        out.maxRangeM = r.readFloat("laser.max_range");
        out.rangeCount = 0;
        out.intensityCount = 0;
        int n = readArrayCounts(r, "laser.ranges", 4, out.rangesM.length);
        float[] ranges = out.rangesM;
        for (int i = 0; i < n; i++) {
            ranges[i] = r.readFloat("laser.ranges");
        }
        out.rangeCount = n;
        int declared = r.readCount("laser.intensity_count", 1, out.intensities.length);
        long at = r.streamPosition();
        int m = r.readBytes("laser.intensity", out.intensities);
        if (m != declared) {
            throw new PlayerProtocolException(at, "laser.intensity", "byte count " + m
                    + " differs from intensity_count " + declared);
        }
        out.intensityCount = m;
        out.id = r.readUnsignedInt("laser.id");
        r.expectEnd("laser.scan");
    }

    /**
     * laser GET_CONFIG reply body (28 bytes).
     *
     * @param w destination
     * @param c the configuration
     */
    public static void writeLaserConfig(XdrWriter w, LaserConfig c) {
        w.writeFloat(c.minAngleRad()).writeFloat(c.maxAngleRad()).writeFloat(c.resolutionRad())
                .writeFloat(c.maxRangeM()).writeFloat(c.rangeResM()).writeInt(c.intensity())
                .writeFloat(c.scanningFrequencyHz());
    }

    /**
     * @param r source
     * @return the configuration
     * @throws PlayerProtocolException if malformed
     */
    public static LaserConfig readLaserConfig(XdrReader r) throws PlayerProtocolException {
        LaserConfig c = new LaserConfig(r.readFloat("laser_config.min_angle"), r.readFloat("laser_config.max_angle"),
                r.readFloat("laser_config.resolution"), r.readFloat("laser_config.max_range"),
                r.readFloat("laser_config.range_res"), r.readU8("laser_config.intensity"),
                r.readFloat("laser_config.scanning_frequency"));
        r.expectEnd("laser_config");
        return c;
    }

    // ---------------------------------------------------------------- ranger

    /**
     * ranger DATA RANGE or DATA INTNS body.
     *
     * @param w destination
     * @param d the values
     */
    public static void writeRangerData(XdrWriter w, RangerData d) {
        w.writeInt(d.count).writeInt(d.count);
        for (int i = 0; i < d.count; i++) {
            w.writeDouble(d.values[i]);
        }
    }

    /**
     * Decodes ranger DATA RANGE or DATA INTNS into a reusable array without allocating.
     *
     * @param r source
     * @param out destination
     * @throws PlayerProtocolException if malformed or larger than {@code out}'s capacity
     */
    public static void readRangerData(XdrReader r, RangerData out) throws PlayerProtocolException {
        out.count = 0;
        int n = readArrayCounts(r, "ranger.values", 8, out.values.length);
        double[] v = out.values;
        for (int i = 0; i < n; i++) {
            v[i] = r.readDouble("ranger.values");
        }
        out.count = n;
        r.expectEnd("ranger.data");
    }

    /**
     * ranger GET_CONFIG reply body (56 bytes).
     *
     * @param w destination
     * @param c the configuration
     */
    public static void writeRangerConfig(XdrWriter w, RangerConfig c) {
        w.writeDouble(c.minAngleRad()).writeDouble(c.maxAngleRad()).writeDouble(c.angularResRad())
                .writeDouble(c.minRangeM()).writeDouble(c.maxRangeM()).writeDouble(c.rangeResM())
                .writeDouble(c.frequencyHz());
    }

    /**
     * @param r source
     * @return the configuration
     * @throws PlayerProtocolException if malformed
     */
    public static RangerConfig readRangerConfig(XdrReader r) throws PlayerProtocolException {
        RangerConfig c = new RangerConfig(r.readDouble("ranger_config.min_angle"),
                r.readDouble("ranger_config.max_angle"), r.readDouble("ranger_config.angular_res"),
                r.readDouble("ranger_config.min_range"), r.readDouble("ranger_config.max_range"),
                r.readDouble("ranger_config.range_res"), r.readDouble("ranger_config.frequency"));
        r.expectEnd("ranger_config");
        return c;
    }

    /**
     * ranger GET_GEOM reply body.
     *
     * @param w destination
     * @param g the geometry
     */
    public static void writeRangerGeometry(XdrWriter w, RangerGeometry g) {
        writePose3d(w, g.pose());
        writeBbox3d(w, g.size());
        w.writeInt(g.elementPoses().size()).writeInt(g.elementPoses().size());
        for (Pose3d p : g.elementPoses()) {
            writePose3d(w, p);
        }
        w.writeInt(g.elementSizes().size()).writeInt(g.elementSizes().size());
        for (Bbox3d b : g.elementSizes()) {
            writeBbox3d(w, b);
        }
    }

    /**
     * @param r source
     * @return the geometry
     * @throws PlayerProtocolException if malformed
     */
    public static RangerGeometry readRangerGeometry(XdrReader r) throws PlayerProtocolException {
        Pose3d pose = readPose3d(r, "ranger_geom.pose");
        Bbox3d size = readBbox3d(r, "ranger_geom.size");
        int np = readArrayCounts(r, "ranger_geom.element_poses", POSE3D_BYTES, MAX_RANGER_ELEMENTS);
        List<Pose3d> poses = new ArrayList<>(np);
        for (int i = 0; i < np; i++) {
            poses.add(readPose3d(r, "ranger_geom.element_poses"));
        }
        int ns = readArrayCounts(r, "ranger_geom.element_sizes", BBOX3D_BYTES, MAX_RANGER_ELEMENTS);
        List<Bbox3d> sizes = new ArrayList<>(ns);
        for (int i = 0; i < ns; i++) {
            sizes.add(readBbox3d(r, "ranger_geom.element_sizes"));
        }
        r.expectEnd("ranger_geom");
        return new RangerGeometry(pose, size, poses, sizes);
    }

    // ---------------------------------------------------------------- simulation

    /**
     * simulation GET_POSE2D / SET_POSE2D body (request or reply). The name is sent with its
     * terminating NUL counted, as Player's C client does.
     *
     * @param w destination
     * @param p model name and pose (the pose is ignored by the server in GET requests)
     */
    public static void writeSimulationPose2d(XdrWriter w, SimulationPose2d p) {
        w.writeCountedString(p.name());
        w.writeDouble(p.xM()).writeDouble(p.yM()).writeDouble(p.yawRad());
    }

    /**
     * @param r source
     * @return model name and pose
     * @throws PlayerProtocolException if malformed
     */
    public static SimulationPose2d readSimulationPose2d(XdrReader r) throws PlayerProtocolException {
        String name = readCountedString(r, "simulation_pose2d.name", MAX_MODEL_NAME_BYTES);
        SimulationPose2d p = new SimulationPose2d(name, r.readDouble("simulation_pose2d.pose.px"),
                r.readDouble("simulation_pose2d.pose.py"), r.readDouble("simulation_pose2d.pose.pa"));
        r.expectEnd("simulation_pose2d");
        return p;
    }
}
