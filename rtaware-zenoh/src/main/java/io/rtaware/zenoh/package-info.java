/**
 * A thin Java API over the official Zenoh implementation: a {@link io.rtaware.zenoh.ZenohSession}
 * opened with an explicit {@link io.rtaware.zenoh.ZenohConfig} (loopback listening and no
 * multicast scouting unless asked), publishers, subscribers that deliver through a
 * {@link io.rtaware.zenoh.ZenohMailbox} into buffers the caller allocated once, and liveliness
 * tokens. The Zenoh engine is the Rust {@code zenoh} crate behind a small JNI library built from
 * {@code src/main/rust} when a Rust toolchain is present; {@link io.rtaware.zenoh.ZenohLibrary}
 * says whether it is and, if not, why. Nothing here knows ROS 2.
 */
package io.rtaware.zenoh;
