/**
 * How recorded values become MCAP messages: standard ROS 2 types as CDR through
 * rtaware-ros2msg's codecs, any other value as JSON of its fields, and rtaware's own timing
 * records as CDR of message types defined here.
 */
package io.rtaware.record.encode;
