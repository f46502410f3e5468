/**
 * The task model: a behavior ({@link io.rtaware.core.task.Task}) with a declared
 * {@link io.rtaware.core.task.Schedule}, the declarations it makes during initialization
 * ({@link io.rtaware.core.task.TaskSetup}) and the {@link io.rtaware.core.task.ErrorPolicy}
 * applied when a cycle throws.
 */
package io.rtaware.core.task;
