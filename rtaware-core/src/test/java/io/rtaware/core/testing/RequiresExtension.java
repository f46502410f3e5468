package io.rtaware.core.testing;

import java.lang.reflect.AnnotatedElement;
import org.junit.jupiter.api.Assertions;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * The rule behind {@link Requires}: skip outside CI, fail under {@code CI=true}. Whether this is CI
 * is the environment variable {@code CI} ({@code true}), unless the JUnit configuration parameter
 * {@value #CI_PARAMETER} says otherwise (its own test runs the rule both ways in one JVM). A helper
 * that needs a requirement halfway through a test (a checker run on a recording the test has just
 * written) applies the same rule with {@link #require(Requirement)}.
 */
public final class RequiresExtension implements BeforeAllCallback, BeforeEachCallback {

    /** JUnit configuration parameter that overrides the {@code CI} environment variable. */
    public static final String CI_PARAMETER = "rtaware.ci";

    @Override
    public void beforeAll(ExtensionContext context) {
        check(context, context.getRequiredTestClass());
    }

    @Override
    public void beforeEach(ExtensionContext context) {
        check(context, context.getRequiredTestMethod());
    }

    private static void check(ExtensionContext context, AnnotatedElement element) {
        Requires requires = element.getAnnotation(Requires.class); // a class's includes its superclasses' (@Inherited)
        if (requires == null) {
            return;
        }
        boolean ci = context.getConfigurationParameter(CI_PARAMETER)
                .orElseGet(() -> String.valueOf(System.getenv("CI"))).equals("true");
        for (Class<? extends Requirement> type : requires.value()) {
            check(instance(type), ci);
        }
    }

    /**
     * The rule, applied where it is called: returns when {@code requirement} is present.
     *
     * @param requirement what the test needs from here on
     * @throws org.opentest4j.TestAbortedException if it is missing outside CI, or excused under CI
     * @throws org.opentest4j.AssertionFailedError if it is missing under {@code CI=true} without an excuse
     */
    public static void require(Requirement requirement) {
        check(requirement, "true".equals(System.getenv("CI")));
    }

    /**
     * @param requirement what a test needs
     * @param ci whether this runs under {@code CI=true}
     * @throws org.opentest4j.TestAbortedException if it is missing outside CI, or excused under CI
     *     (JUnit counts the test as skipped)
     * @throws org.opentest4j.AssertionFailedError if it is missing under CI without an excuse (a failure)
     */
    static void check(Requirement requirement, boolean ci) {
        String reason = requirement.missingReason();
        if (reason == null) {
            return;
        }
        String missing = "missing " + requirement.name() + ": " + reason;
        if (!ci) {
            Assumptions.abort("skipped: " + missing);
        }
        String excuse = requirement.excusedUnderCi();
        if (excuse != null) {
            Assumptions.abort("skipped under CI=true (" + excuse + "): " + missing);
        }
        Assertions.fail("CI=true but " + missing);
    }

    private static Requirement instance(Class<? extends Requirement> type) {
        try {
            return type.getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(type.getName() + " needs a public constructor without parameters", e);
        }
    }
}
