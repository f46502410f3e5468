/**
 * The one way a background loop of rtaware runs (the console reporter, the live view's
 * publisher, the ROS 2 exporter, the run's referee, the recorder's writer, the simulator's world,
 * accept and ROS 2 loops): an Agrona
 * {@link org.agrona.concurrent.Agent} on a thread of its own, started and closed by
 * {@link io.rtaware.core.agent.AgentThread}: {@code onStart}, then {@code doWork} and the idle
 * strategy in turn, every error to one handler and a counter, {@code onClose} on the same
 * thread, and a close that wakes the thread and joins it, with a timeout after which it
 * interrupts or, for a writer finishing a file, without one. An agent whose work is due at
 * moments of world time idles with a {@link io.rtaware.core.monitor.WorldClockIdleStrategy},
 * which waits through the clock waiter the monitor's executors wait with.
 */
package io.rtaware.core.agent;
