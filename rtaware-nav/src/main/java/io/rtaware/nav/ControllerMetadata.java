package io.rtaware.nav;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * The navigation controller's configuration in a recording's {@code rtaware.run} metadata: the
 * whole {@link NavConfig} as JSON under {@value #NAV_CONFIG} (what replay rebuilds the controller
 * from, exactly: {@link #configuration}, stored as the replay provider's configuration), plus
 * readable entries for people and other tools (robot model, top speed, inflation margin, grid,
 * waypoints, cores: {@link #entries}). Stateless and thread-safe.
 */
public final class ControllerMetadata {

    /** Metadata entry holding the controller's configuration as JSON. */
    public static final String NAV_CONFIG = "nav_config";
    /** Metadata entry naming the robot model the controller's configuration was derived from. */
    public static final String ROBOT_MODEL = "robot_model";
    /** Metadata entry holding the recording machine's core count. */
    public static final String CORES = "cores";

    private static final ObjectMapper JSON = new ObjectMapper();

    private ControllerMetadata() {
    }

    /**
     * @param config the controller's configuration
     * @return what replay rebuilds the controller from: {@value #NAV_CONFIG}, the configuration as JSON
     */
    public static Map<String, String> configuration(NavConfig config) {
        try {
            return Map.of(NAV_CONFIG, JSON.writeValueAsString(config));
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("NavConfig is not serializable", e);
        }
    }

    /**
     * @param config the controller's configuration
     * @param robotModel the robot model's name
     * @param cores the recording machine's core count
     * @return the readable metadata entries to add to {@code rtaware.run} (a map the caller may change)
     */
    public static Map<String, String> entries(NavConfig config, String robotModel, int cores) {
        Map<String, String> m = new LinkedHashMap<>();
        m.put(ROBOT_MODEL, robotModel);
        m.put("top_speed_mps", Double.toString(config.robot().topSpeedMps()));
        m.put("inflation_margin_m", Double.toString(config.planner().inflationMarginM()));
        m.put("grid", String.format(Locale.ROOT, "%s m cells, origin (%s, %s), %s x %s m",
                config.grid().resolutionM(), config.grid().originXM(), config.grid().originYM(),
                config.grid().widthM(), config.grid().heightM()));
        m.put("waypoints", config.course().waypoints().stream()
                .map(p -> p.xM() + "," + p.yM()).collect(Collectors.joining(" ")));
        m.put(CORES, Integer.toString(cores));
        return m;
    }

    /**
     * @param configuration what {@link #configuration} stored (or an older recording's whole
     *     {@code rtaware.run} metadata, which held {@value #NAV_CONFIG} itself)
     * @return the controller's configuration as recorded
     * @throws IllegalArgumentException if there is none or it is not readable
     */
    public static NavConfig navConfig(Map<String, String> configuration) {
        String json = configuration.get(NAV_CONFIG);
        if (json == null) {
            throw new IllegalArgumentException("its controller configuration has no " + NAV_CONFIG);
        }
        try {
            return JSON.readValue(json, NavConfig.class);
        } catch (JsonProcessingException e) {
            throw new IllegalArgumentException("its " + NAV_CONFIG + " metadata is not readable: "
                    + e.getOriginalMessage());
        }
    }

    /**
     * The recorded configuration with other periods, everything derived from the periods (the
     * mediator's period unless named, its maximum request ages) derived again, as {@code run}
     * derives them.
     *
     * @param recorded the recorded configuration
     * @param periodsNs period of each behavior, and optionally of the mediator, by task name
     * @return the configuration to run
     * @throws IllegalArgumentException if a name is neither a behavior's task nor the mediator
     */
    public static NavConfig withPeriods(NavConfig recorded, Map<String, Long> periodsNs) {
        for (String task : periodsNs.keySet()) {
            if (!Behavior.taskNames().contains(task) && !task.equals(NavConfig.MEDIATOR)) {
                throw new IllegalArgumentException("unknown task '" + task + "'; tasks whose period can be set: "
                        + String.join(", ", Behavior.taskNames()) + ", " + NavConfig.MEDIATOR);
            }
        }
        NavConfig.Grid g = recorded.grid();
        NavConfig.Robot r = recorded.robot();
        NavConfig.Avoider a = recorded.avoider();
        NavConfig.Follower f = recorded.follower();
        NavConfig.Builder b = NavConfig.builder()
                .grid(g.resolutionM(), g.originXM(), g.originYM(), g.widthM(), g.heightM())
                .robotRadiusM(r.radiusM())
                .topSpeedMps(r.topSpeedMps())
                .maxOmegaRadPerSec(r.maxOmegaRadPerSec())
                .reactionLimits(r.stoppingDistanceM(), r.laserDelayNs())
                .laserMinRangeM(r.laserMinRangeM())
                .obstacleSpeedMps(r.obstacleSpeedMps())
                .inflationMarginM(recorded.planner().inflationMarginM())
                .unknownCostFactor(recorded.planner().unknownCostFactor())
                .lookaheadM(f.lookaheadM())
                .turnInPlaceRad(f.turnInPlaceRad())
                .goalToleranceM(f.goalToleranceM())
                .avoidance(a.rangeM(), a.halfAngleRad(), a.stopRangeM(), a.speedMps())
                .laserMaxAgeNs(recorded.maxAges().laserNs())
                .odometryMaxAgeNs(recorded.maxAges().odometryNs())
                .waypoints(recorded.course().waypoints())
                .externalWaypoints(recorded.course().external());
        for (Behavior behavior : Behavior.values()) {
            b.periodNs(behavior, periodsNs.getOrDefault(behavior.taskName(), recorded.periods().ns(behavior)));
        }
        if (periodsNs.containsKey(NavConfig.MEDIATOR)) {
            b.mediatorPeriodNs(periodsNs.get(NavConfig.MEDIATOR)); // named (period advice does): not derived
        }
        return b.build();
    }
}
