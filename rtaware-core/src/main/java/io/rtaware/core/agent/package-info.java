/**
 * The one way a background loop of rtaware runs (the console reporter, the live view's
 * publisher, the exporter, the referee, the simulator's loops): an Agrona
 * {@link org.agrona.concurrent.Agent} on a thread of its own, started and closed by
 * {@link io.rtaware.core.agent.AgentThread}: {@code onStart}, then {@code doWork} and the idle
 * strategy in turn, every error to one handler and a counter, {@code onClose} on the same
 * thread, and a close that joins with a timeout.
 */
package io.rtaware.core.agent;
