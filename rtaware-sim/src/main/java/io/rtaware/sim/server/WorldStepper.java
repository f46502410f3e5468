package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.sim.world.World;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * Steps the world and hands what it published to the clients: after each step every device a
 * client subscribes to adds its DATA messages, and every client gets the batch (its queue keeps
 * what it subscribes to). {@link #run(Clock)} follows a clock: it aims at fixed steps of world
 * time, waits via {@link Clock#toWallNanos(long)} (so with a scaled clock the world runs K times
 * faster), and when it falls behind by more than {@value #MAX_BACKLOG_STEPS} steps takes the
 * excess in one long step. Steps run on one thread at a time.
 */
final class WorldStepper {

    /** Most fixed steps taken to catch up; a larger backlog is taken in one long step. */
    static final long MAX_BACKLOG_STEPS = 1000;

    private final SharedWorld world;
    private final List<DeviceHandler> devices;
    private final Iterable<ClientSession> clients;
    private final long stepPeriodNs;
    private volatile boolean running = true;
    /** The clock reading at which the world's time was 0; {@link Long#MIN_VALUE} until {@link #run} starts. */
    private volatile long clockOriginNs = Long.MIN_VALUE;

    /**
     * @param world the world
     * @param devices the devices that publish data, in the order their data is sent
     * @param clients the connected clients (iterated on every step)
     * @param stepPeriodNs the world-time step {@link #run} aims at
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

    /** Steps on {@code clock} until {@link #stop()}. */
    void run(Clock clock) {
        long last = clock.nanos();
        clockOriginNs = last - world.read(World::timeNs); // from here on, world time = clock - origin, stepped
        while (running) {
            long target = last + stepPeriodNs;
            long now = clock.nanos();
            while (running && now < target) {
                LockSupport.parkNanos(Math.max(1_000L, clock.toWallNanos(target - now)));
                now = clock.nanos();
            }
            if (!running) {
                return;
            }
            long behind = now - last;
            long maxBacklogNs = MAX_BACKLOG_STEPS * stepPeriodNs;
            if (behind > maxBacklogNs) {
                // cannot keep up (or the clock jumped): take the excess in one long step
                step(behind - maxBacklogNs);
                behind = maxBacklogNs;
            }
            while (behind >= stepPeriodNs) {
                step(stepPeriodNs);
                behind -= stepPeriodNs;
            }
            last = now - behind;
        }
    }

    /**
     * @return the clock reading at which the world's time was 0 ({@link #run} keeps world time
     *     at the clock's reading minus this, in whole steps), or {@link Long#MIN_VALUE} before
     *     {@link #run} has started
     */
    long clockOriginNs() {
        return clockOriginNs;
    }

    /** Makes {@link #run} return (within one wait). */
    void stop() {
        running = false;
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
