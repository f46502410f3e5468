package io.rtaware.ros2msg;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.ros2msg.cdr.CdrReader;
import io.rtaware.ros2msg.cdr.CdrWriter;
import io.rtaware.ros2msg.value.PlanarPose;
import org.junit.jupiter.api.Test;

/** TFMessage of planar transforms, written and read back. */
class TransformMessagesTest {

    @Test
    void transformsReadBackAsWritten() {
        CdrWriter out = new CdrWriter(1024);
        TransformMessages.begin(out, 2);
        TransformMessages.transform(out, 1_700_000_000_123_456_789L, "odom", "base_link", 1.5, -2.25, 0.5);
        TransformMessages.transform(out, 42L, "base_link", "laser", 0, 0, 0);
        CdrReader in = new CdrReader().wrap(out.buffer(), 0, out.size());
        Ros2Header header = new Ros2Header();
        StringBuilder child = new StringBuilder();
        PlanarPose pose = new PlanarPose();
        assertEquals(2, TransformMessages.count(in), "transforms in the message");
        TransformMessages.read(in, header, child, pose);
        assertEquals(1_700_000_000_123_456_789L, header.stampNs, "stamp");
        assertEquals("odom", header.frameId.toString(), "parent");
        assertEquals("base_link", child.toString(), "child");
        assertEquals(1.5, pose.xM, "x");
        assertEquals(-2.25, pose.yM, "y");
        assertEquals(0.5, pose.yawRad, 1e-12, "yaw");
        TransformMessages.read(in, header, child, pose);
        assertEquals(42L, header.stampNs, "second stamp");
        assertEquals("base_link", header.frameId.toString(), "second parent");
        assertEquals("laser", child.toString(), "second child");
        assertEquals(0, in.remaining(), "nothing left over");
    }
}
