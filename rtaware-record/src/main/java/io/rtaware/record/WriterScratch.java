package io.rtaware.record;

import io.rtaware.record.encode.ByteBuf;
import io.rtaware.ros2msg.Ros2Header;
import io.rtaware.ros2msg.cdr.CdrWriter;

/** The writer thread's encoding buffers, allocated once and reused for every message. */
final class WriterScratch {

    private static final int CDR_CAPACITY = 2 << 20;

    /** CDR of the message being written. */
    final CdrWriter cdr = new CdrWriter(CDR_CAPACITY);
    /** JSON of the state being written. */
    final ByteBuf json = new ByteBuf(1 << 16);
    /** The header of a ROS 2 message being written. */
    final Ros2Header header = new Ros2Header();
}
