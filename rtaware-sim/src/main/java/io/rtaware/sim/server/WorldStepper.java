package io.rtaware.sim.server;

import io.rtaware.core.monitor.WorldClockIdleStrategy;
import io.rtaware.core.time.Clock;
import io.rtaware.sim.world.World;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentTerminationException;

/**
 * Steps the world and hands what it published to the clients: after each step every device a
 * client subscribes to adds its DATA messages, and every client gets the batch (its queue keeps
 * what it subscribes to). {@link #stepping} follows a clock: it aims at fixed steps of world
 * time, waits for the next one with a {@link WorldClockIdleStrategy} (the wall time left, so with
 * a scaled clock the world runs K times faster; on a manual clock until it is advanced), and when it falls behind by more than {@value #MAX_BACKLOG_STEPS} steps takes the
 * excess in one long step. Steps run on one thread at a time.
 */
final class WorldStepper {

    /** Most fixed steps taken to catch up; a larger backlog is taken in one long step. */
    static final long MAX_BACKLOG_STEPS = 1000;

    private final SharedWorld world;
    private final List<DeviceHandler> devices;
    private final Iterable<ClientSession> clients;
    private final long stepPeriodNs;
    /** The clock reading at which the world's time was 0; {@link Long#MIN_VALUE} until the stepping starts. */
    private volatile long clockOriginNs = Long.MIN_VALUE;
    /** Counted down once {@link #clockOriginNs} is set. */
    private final CountDownLatch originTaken = new CountDownLatch(1);

    /**
     * @param world the world
     * @param devices the devices that publish data, in the order their data is sent
     * @param clients the connected clients (iterated on every step)
     * @param stepPeriodNs the world-time step {@link #stepping} aims at
     */
    WorldStepper(SharedWorld world, List<DeviceHandler> devices, Iterable<ClientSession> clients, long stepPeriodNs) {
        this.world = world;
        this.devices = List.copyOf(devices);
        this.clients = clients;
        this.stepPeriodNs = stepPeriodNs;
    }

    /**
     * Advances the world by {@code dtNs} and delivers the data it published.
     *
     * @param dtNs world nanoseconds, not negative
     */
    void step(long dtNs) {
        List<Outgoing> batch = new ArrayList<>(4);
        world.step(dtNs, w -> {
            double t = w.timeS();
            for (DeviceHandler d : devices) {
                if (anySubscribed(DeviceHandler.key(d.interf(), 0))) {
                    d.publish(w, t, batch);
                }
            }
        });
        if (batch.isEmpty()) {
            return;
        }
        for (ClientSession c : clients) {
            c.deliver(batch);
        }
    }

    /**
     * The stepping loop on {@code clock}, to run on an {@link io.rtaware.core.agent.AgentThread}
     * with {@code idle}: each duty cycle takes the steps that are due, or names the next step's
     * world time for the idle to wait for (a wait that closing the thread cuts short). A step that throws ends the
     * loop (an {@link AgentTerminationException} with the step's error as its cause): the world
     * stops, as a crashed simulator's would, rather than failing again every step.
     *
     * @param clock world time
     * @param idle the idle strategy the loop runs with, on {@code clock}
     * @param roleName the thread's name
     * @return the loop
     */
    Agent stepping(Clock clock, WorldClockIdleStrategy idle, String roleName) {
        return new Stepping(clock, idle, roleName);
    }

    /** Follows a clock: fixed steps of world time, a backlog beyond {@value #MAX_BACKLOG_STEPS} steps in one. */
    private final class Stepping implements Agent {
        private final Clock clock;
        private final WorldClockIdleStrategy idle;
        private final String roleName;
        /** World time up to which the world has been stepped (the stepping thread only). */
        private long lastNs;

        Stepping(Clock clock, WorldClockIdleStrategy idle, String roleName) {
            this.clock = clock;
            this.idle = idle;
            this.roleName = roleName;
        }

        @Override
        public void onStart() {
            lastNs = clock.nanos();
            clockOriginNs = lastNs - world.read(World::timeNs); // from here on, world time = clock - origin, stepped
            originTaken.countDown();
        }

        @Override
        public int doWork() {
            try {
                return stepDue();
            } catch (RuntimeException e) {
                throw new AgentTerminationException(e);
            }
        }

        private int stepDue() {
            long target = lastNs + stepPeriodNs;
            long now = clock.nanos();
            if (now < target) {
                idle.wakeAt(target);
                return 0;
            }
            long behind = now - lastNs;
            long maxBacklogNs = MAX_BACKLOG_STEPS * stepPeriodNs;
            int steps = 0;
            if (behind > maxBacklogNs) {
                // cannot keep up (or the clock jumped): take the excess in one long step
                step(behind - maxBacklogNs);
                behind = maxBacklogNs;
                steps++;
            }
            while (behind >= stepPeriodNs) {
                step(stepPeriodNs);
                behind -= stepPeriodNs;
                steps++;
            }
            lastNs = now - behind;
            return steps;
        }

        @Override
        public String roleName() {
            return roleName;
        }
    }

    /**
     * Waits for the stepping's first clock reading.
     *
     * @param timeoutNs the longest wait, ns of wall time
     * @return the clock reading at which the world's time was 0 (the stepping keeps world time at
     *     the clock's reading minus this, in whole steps), or {@link Long#MIN_VALUE} if the
     *     stepping has not started within the wait
     * @throws InterruptedException if the waiting thread is interrupted
     */
    long awaitClockOriginNs(long timeoutNs) throws InterruptedException {
        originTaken.await(timeoutNs, TimeUnit.NANOSECONDS);
        return clockOriginNs;
    }

    private boolean anySubscribed(int deviceKey) {
        for (ClientSession c : clients) {
            if (c.subscribed(deviceKey)) {
                return true;
            }
        }
        return false;
    }
}
