package io.rtaware.replay;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.record.RecordingPlan;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Finding a recording's controller among the providers registered in META-INF/services. */
class ReplayProvidersTest {

    /** A provider registered in this module's test resources: one task whose period is configured. */
    public static final class Counter implements ReplayableController {
        @Override
        public String id() {
            return "test.counter";
        }

        @Override
        public List<TaskSpec> tasks(Map<String, String> configuration, Map<String, Long> periodsNs) {
            long periodNs = periodsNs.getOrDefault("count", Long.parseLong(configuration.get("period_ns")));
            return List.of(new TaskSpec("count", Schedule.periodic(Duration.ofNanos(periodNs)), ErrorPolicy.CONTINUE,
                    new Task() {
                        @Override
                        public void initialize(TaskSetup setup) {
                        }

                        @Override
                        public void execute(long nowNs) {
                        }
                    }));
        }

        @Override
        public boolean recognizesUnnamed(Map<String, String> runMetadata) {
            return runMetadata.containsKey("period_ns");
        }
    }

    private final ReplayProviders providers = ReplayProviders.load(ReplayProvidersTest.class.getClassLoader());

    @Test
    void theRecordingNamesItsProviderAndItsConfiguration() {
        RecordingPlan plan = ReplayableController.describe(new RecordingPlan().metadata("scenario", "s"), "test.counter",
                Map.of("period_ns", "20000000"));
        assertEquals("test.counter", plan.metadata().get(ReplayableController.CONTROLLER));

        ReplayProviders.RecordedController controller = providers.controllerOf(plan.metadata());

        assertEquals("test.counter", controller.provider().id());
        assertEquals(Map.of("period_ns", "20000000"), controller.configuration(), "the configuration, without the prefix");
        assertEquals(Map.of("count", 20_000_000L), controller.recordedPeriodsNs());
        assertEquals(Map.of("count", 5_000_000L), ReplayProviders.periodsNs(controller.tasks(Map.of("count", 5_000_000L))));
    }

    @Test
    void aRecordingThatNamesNoProviderIsRecognizedByItsMetadata() {
        Map<String, String> old = Map.of("period_ns", "10000000", "scenario", "s");
        ReplayProviders.RecordedController controller = providers.controllerOf(old);
        assertEquals("test.counter", controller.provider().id());
        assertEquals(old, controller.configuration(), "an unnamed recording's configuration is its whole metadata");

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> providers.controllerOf(Map.of("scenario", "s")));
        assertTrue(e.getMessage().contains("names no controller"), e.getMessage());
    }

    @Test
    void aProviderThatIsNotFoundIsNamedWithTheWayToFindIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> providers.controllerOf(Map.of(ReplayableController.CONTROLLER, "com.example.robot")));
        assertTrue(e.getMessage().contains("'com.example.robot'") && e.getMessage().contains("--classpath"),
                e.getMessage());
        assertTrue(e.getMessage().contains("test.counter"), "names the providers found: " + e.getMessage());
    }
}
