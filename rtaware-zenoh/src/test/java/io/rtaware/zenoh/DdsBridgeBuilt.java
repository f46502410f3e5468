package io.rtaware.zenoh;

import io.rtaware.core.testing.Requirement;

/**
 * The DDS bridge's executable (built with the native layer where cmake and libclang are there):
 * {@code @Requires(DdsBridgeBuilt.class)}. Under CI it is required wherever the native layer is
 * ({@code .ci/run} installs cmake and libclang where it has cargo); CI may lack it only with the
 * native layer, under {@code RTAWARE_NO_RUST=1}.
 */
public final class DdsBridgeBuilt implements Requirement {

    @Override
    public String name() {
        return "the DDS bridge";
    }

    @Override
    public String missingReason() {
        return DdsBridge.unavailableReason();
    }

    @Override
    public String excusedUnderCi() {
        return ZenohLibrary.unavailableReason() != null ? NativeZenohLayer.noRust() : null;
    }
}
