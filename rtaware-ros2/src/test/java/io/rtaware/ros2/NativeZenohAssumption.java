package io.rtaware.ros2;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import io.rtaware.zenoh.ZenohLibrary;

/** Skips a test when the native Zenoh layer is missing, except in CI (CI=true), where it fails. */
public final class NativeZenohAssumption {

    private NativeZenohAssumption() {
    }

    /** Call first in a test that needs Zenoh. */
    public static void require() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null && "true".equals(System.getenv("CI"))) {
            fail("CI=true but " + reason);
        }
        assumeTrue(reason == null, () -> "skipped: " + reason);
    }
}
