package io.rtaware.ros2;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.zenoh.ZenohLibrary;

/** Skips a test when the native Zenoh layer is missing, except in CI (CI=true), where it fails unless
 * .ci/run found no Rust toolchain and said so (RTAWARE_NO_RUST=1). */
public final class NativeZenohAssumption {

    private NativeZenohAssumption() {
    }

    /** Call first in a test that needs Zenoh. */
    public static void require() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null && "true".equals(System.getenv("CI")) && !"1".equals(System.getenv("RTAWARE_NO_RUST"))) {
            fail("CI=true but " + reason + " (.ci/run sets RTAWARE_NO_RUST=1 when the machine has no Rust toolchain)");
        }
        assumeTrue(reason == null, () -> "skipped: " + reason);
    }
}
