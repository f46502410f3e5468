package io.rtaware.zenoh;

import io.rtaware.core.testing.Requirement;

/**
 * The native Zenoh layer (the JNI library built by cargo): {@code @Requires(NativeZenohLayer.class)}.
 * CI may lack it only where {@code .ci/run} found no Rust toolchain and said so with
 * {@code RTAWARE_NO_RUST=1}.
 */
public final class NativeZenohLayer implements Requirement {

    /** @return why CI may lack the native layer here, or {@code null} */
    static String noRust() {
        return "1".equals(System.getenv("RTAWARE_NO_RUST")) ? "RTAWARE_NO_RUST=1: no Rust toolchain on this machine" : null;
    }

    @Override
    public String name() {
        return "the native Zenoh layer";
    }

    @Override
    public String missingReason() {
        return ZenohLibrary.unavailableReason();
    }

    @Override
    public String excusedUnderCi() {
        return noRust();
    }
}
