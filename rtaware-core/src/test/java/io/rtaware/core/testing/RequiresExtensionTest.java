package io.rtaware.core.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

/**
 * The rule of {@link Requires}, run through the JUnit Platform as surefire runs a test: a missing
 * requirement skips outside CI with a reason naming it, fails under {@code CI=true}, skips under
 * CI when the requirement says why CI may lack it; a present one runs the test.
 */
class RequiresExtensionTest {

    /** A requirement whose answers are fixed. */
    private abstract static class Fixed implements Requirement {
        private final String name;
        private final String missing;
        private final String excuse;

        Fixed(String name, String missing, String excuse) {
            this.name = name;
            this.missing = missing;
            this.excuse = excuse;
        }

        @Override
        public String name() {
            return name;
        }

        @Override
        public String missingReason() {
            return missing;
        }

        @Override
        public String excusedUnderCi() {
            return excuse;
        }
    }

    /** Never present. */
    public static final class Unicorn extends Fixed {
        /** As {@link Requires} makes it. */
        public Unicorn() {
            super("the unicorn", "none was ever seen here", null);
        }
    }

    /** Never present, and CI may lack it. */
    public static final class ExcusedUnicorn extends Fixed {
        /** As {@link Requires} makes it. */
        public ExcusedUnicorn() {
            super("the excused unicorn", "none was ever seen here", "CI said it has none");
        }
    }

    /** Always present. */
    public static final class Air extends Fixed {
        /** As {@link Requires} makes it. */
        public Air() {
            super("air", null, null);
        }
    }

    // The fixtures below are nested, so surefire does not run them on their own (it excludes
    // nested classes); each test here runs one of them through a launcher of its own.

    /** A method that needs the unicorn. */
    static final class NeedsAUnicorn {
        @Test
        @Requires(Unicorn.class)
        void ridesIt() {
        }
    }

    /** A class whose every test needs air and the excused unicorn. */
    @Requires({Air.class, ExcusedUnicorn.class})
    static final class NeedsAnExcusedUnicorn {
        @Test
        void ridesIt() {
        }
    }

    /** A method that needs only air. */
    static final class NeedsAir {
        @Test
        @Requires(Air.class)
        void breathes() {
        }
    }

    /** What the launcher reported of one fixture: each outcome in words. */
    private static List<String> run(Class<?> fixture, boolean ci) {
        List<String> outcomes = new ArrayList<>();
        LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                .selectors(selectClass(fixture))
                .configurationParameter(RequiresExtension.CI_PARAMETER, String.valueOf(ci))
                .build();
        Launcher launcher = LauncherFactory.create();
        launcher.execute(request, new TestExecutionListener() {
            @Override
            public void executionSkipped(TestIdentifier id, String reason) {
                outcomes.add(id.getDisplayName() + " disabled: " + reason);
            }

            @Override
            public void executionFinished(TestIdentifier id, TestExecutionResult result) {
                if (id.isContainer() && result.getStatus() == TestExecutionResult.Status.SUCCESSFUL) {
                    return;
                }
                outcomes.add(id.getDisplayName() + " " + result.getStatus() + result.getThrowable()
                        .map(t -> ": " + t.getClass().getSimpleName() + ": " + t.getMessage()).orElse(""));
            }
        });
        return outcomes;
    }

    @Test
    void outsideCiAMissingRequirementSkipsTheTestNamingIt() {
        assertEquals(List.of("ridesIt() ABORTED: TestAbortedException: skipped: missing the unicorn: "
                + "none was ever seen here"), run(NeedsAUnicorn.class, false));
    }

    @Test
    void underCiAMissingRequirementFailsTheTestNamingIt() {
        assertEquals(List.of("ridesIt() FAILED: AssertionFailedError: CI=true but missing the unicorn: "
                + "none was ever seen here"), run(NeedsAUnicorn.class, true));
    }

    @Test
    void underCiAnExcusedRequirementSkipsTheWholeClassSayingWhy() {
        assertEquals(List.of("RequiresExtensionTest$NeedsAnExcusedUnicorn ABORTED: TestAbortedException: skipped under CI=true "
                + "(CI said it has none): missing the excused unicorn: none was ever seen here"),
                run(NeedsAnExcusedUnicorn.class, true));
    }

    @Test
    void aPresentRequirementRunsTheTest() {
        assertEquals(List.of("breathes() SUCCESSFUL"), run(NeedsAir.class, true));
        assertEquals(List.of("breathes() SUCCESSFUL"), run(NeedsAir.class, false));
    }
}
