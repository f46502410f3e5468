/**
 * The robot data shared through the data store: mutable, fixed-capacity buffers whose
 * {@code copyFrom} allocates nothing.
 */
package io.rtaware.robot.msg;
