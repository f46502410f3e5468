package io.rtaware.core.testing;

import java.lang.annotation.Documented;
import java.lang.annotation.ElementType;
import java.lang.annotation.Inherited;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;
import org.junit.jupiter.api.extension.ExtendWith;

/**
 * What a test class or method needs from the machine. Outside CI a test whose requirement is
 * missing is skipped with a reason that names the requirement; under {@code CI=true} it fails,
 * since {@code .ci/run} installs every requirement, unless the requirement says why CI may lack it
 * here ({@link Requirement#excusedUnderCi()}, such as {@code RTAWARE_NO_RUST=1} for the native
 * layer). On a class, every test of it (and its {@code @BeforeAll}) waits on the check.
 */
@Documented
@Inherited
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.TYPE, ElementType.METHOD})
@ExtendWith(RequiresExtension.class)
public @interface Requires {

    /** @return the requirements, each checked in turn */
    Class<? extends Requirement>[] value();
}
