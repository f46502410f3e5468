package io.rtaware.core.conditions;

import io.rtaware.core.testing.Requirement;

/**
 * A CPU controller of cgroup v1 or v2 on which this process may create groups (root, or a
 * delegated hierarchy): checked by creating a group and removing it.
 */
public final class WritableCpuController implements Requirement {

    @Override
    public String name() {
        return "a writable cgroup CPU controller (root)";
    }

    @Override
    public String missingReason() {
        return CpuQuota.refusal(1.0).orElse(null);
    }

    @Override
    public String excusedUnderCi() {
        return "CI runs its tests as an ordinary user in a container, without a writable cgroup hierarchy";
    }
}
