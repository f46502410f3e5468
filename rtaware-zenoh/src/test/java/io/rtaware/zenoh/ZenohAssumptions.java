package io.rtaware.zenoh;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/** Skips a test when the native Zenoh layer is missing, except in CI (CI=true), where it fails. */
final class ZenohAssumptions {

    private ZenohAssumptions() {
    }

    static void requireNativeZenoh() {
        String reason = ZenohLibrary.unavailableReason();
        if (reason != null && "true".equals(System.getenv("CI"))) {
            fail("CI=true but " + reason);
        }
        assumeTrue(reason == null, () -> "skipped: " + reason);
    }
}
