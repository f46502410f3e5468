package io.rtaware.robotrun;

import io.rtaware.core.task.TaskSpec;
import io.rtaware.nav.ControllerMetadata;
import io.rtaware.nav.NavController;
import io.rtaware.replay.ReplayableController;
import java.util.List;
import java.util.Map;

/**
 * The paper's navigation controller as a replay provider: rebuilt from its recorded
 * {@link io.rtaware.nav.NavConfig} ({@link ControllerMetadata}), with other behavior periods
 * for a what-if replay. Registered in {@code META-INF/services}; recordings made before
 * providers, which hold {@value ControllerMetadata#NAV_CONFIG} among their metadata and name no
 * controller, are recognized as this controller's. Stateless and thread-safe.
 */
public final class NavReplayProvider implements ReplayableController {

    /** The id recordings of {@code rtaware run} name this provider by. */
    public static final String ID = "io.rtaware.nav";

    /** Creates the provider (for {@link java.util.ServiceLoader}). */
    public NavReplayProvider() {
    }

    @Override
    public String id() {
        return ID;
    }

    @Override
    public List<TaskSpec> tasks(Map<String, String> configuration, Map<String, Long> periodsNs) {
        return new NavController(ControllerMetadata.withPeriods(ControllerMetadata.navConfig(configuration), periodsNs))
                .taskSpecs();
    }

    @Override
    public boolean recognizesUnnamed(Map<String, String> runMetadata) {
        return runMetadata.containsKey(ControllerMetadata.NAV_CONFIG);
    }
}
