/**
 * CDR as ROS 2 uses it (XCDR1, plain CDR, little endian): a writer and a reader over buffers
 * allocated once, so that encoding and decoding a message allocates nothing in steady state.
 * Every buffer starts with the 4-byte encapsulation header {@code 00 01 00 00}; primitive
 * fields are aligned to their size counted from the end of that header.
 */
package io.rtaware.ros2msg.cdr;
