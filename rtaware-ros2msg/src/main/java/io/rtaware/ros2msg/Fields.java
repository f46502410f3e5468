package io.rtaware.ros2msg;

import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;

/** Writers and readers of the nested types the codecs share (time, header, planar pose). */
final class Fields {

    static final long NS_PER_S = 1_000_000_000L;

    private Fields() {
    }

    /** {@code builtin_interfaces/Time}: sec = floor(ns / 1e9), nanosec = the rest. */
    static void writeTime(CdrWriter w, long stampNs) {
        w.writeInt32((int) Math.floorDiv(stampNs, NS_PER_S));
        w.writeInt32((int) Math.floorMod(stampNs, NS_PER_S));
    }

    static long readTime(CdrReader r) {
        long sec = r.readInt32();
        long nanosec = r.readInt32() & 0xffffffffL;
        return sec * NS_PER_S + nanosec;
    }

    static void writeHeader(CdrWriter w, Ros2Header h) {
        writeTime(w, h.stampNs);
        w.writeString(h.frameId);
    }

    static void readHeader(CdrReader r, Ros2Header h) {
        h.stampNs = readTime(r);
        h.frameId.setLength(0);
        r.readString(h.frameId);
    }

    static void skipHeader(CdrReader r) {
        readTime(r);
        r.skipString();
    }

    /** {@code geometry_msgs/Pose} in the plane: z = 0, rotation about z by {@code yaw}. */
    static void writePlanarPose(CdrWriter w, double xM, double yM, double yawRad) {
        w.writeFloat64(xM);
        w.writeFloat64(yM);
        w.writeFloat64(0.0);
        w.writeFloat64(0.0);
        w.writeFloat64(0.0);
        w.writeFloat64(StrictMath.sin(yawRad / 2));
        w.writeFloat64(StrictMath.cos(yawRad / 2));
    }

    /** Reads a {@code geometry_msgs/Pose}, keeping x, y and the heading about z. */
    static void readPlanarPose(CdrReader r, PlanarPose into) {
        double x = r.readFloat64();
        double y = r.readFloat64();
        r.readFloat64();
        double qx = r.readFloat64();
        double qy = r.readFloat64();
        double qz = r.readFloat64();
        double qw = r.readFloat64();
        into.set(x, y, StrictMath.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz)));
    }

    static void writeVector3(CdrWriter w, double x, double y, double z) {
        w.writeFloat64(x);
        w.writeFloat64(y);
        w.writeFloat64(z);
    }
}
