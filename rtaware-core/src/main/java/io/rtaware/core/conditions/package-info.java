/**
 * The conditions a run was made under, so that every number rtaware prints can be read
 * honestly: the machine, the operating system and the JVM as they were
 * ({@link io.rtaware.core.conditions.StaticConditions}), what disturbed the run as measured
 * from the OS and the JVM over it ({@link io.rtaware.core.conditions.MeasuredConditions}), and
 * a verdict by a stated rule ({@link io.rtaware.core.conditions.MachineVerdict}: quiet, busy or
 * disturbed). {@link io.rtaware.core.conditions.ConditionsMeter} takes the readings at the start
 * and the end of a run. Everything is read through {@link io.rtaware.core.conditions.HostFiles}
 * (a file root, {@code /} in production, fixture files in tests) and
 * {@link io.rtaware.core.conditions.JvmProbe} (the platform's management beans, or a fake), so a
 * library user has it without the command line, and tests run on fixtures.
 */
package io.rtaware.core.conditions;
