package io.rtaware.sim.server;

import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotConfig;
import io.rtaware.sim.world.World;
import java.util.Objects;
import java.util.function.Consumer;
import java.util.function.Function;

/**
 * The served {@link World} behind one lock, and the simulation time of the last step (the time
 * stamp of replies). The stepping thread and the clients' reader threads go through here.
 * Thread-safe.
 */
final class SharedWorld {

    private final World world;
    private final Object lock = new Object();
    private volatile double timeS;

    SharedWorld(World world) {
        this.world = Objects.requireNonNull(world, "world");
        this.timeS = world.timeS();
    }

    /**
     * @param f what to read; must not keep the world
     * @param <T> the result type
     * @return f's result, computed under the lock
     */
    <T> T read(Function<World, T> f) {
        synchronized (lock) {
            return f.apply(world);
        }
    }

    /** @param change what to do to the world, under the lock */
    void update(Consumer<World> change) {
        synchronized (lock) {
            change.accept(world);
        }
    }

    /**
     * Steps the world and records its new time; then, still under the lock, {@code afterStep}
     * reads what the step produced.
     */
    void step(long dtNs, Consumer<World> afterStep) {
        synchronized (lock) {
            world.step(dtNs);
            timeS = world.timeS();
            afterStep.accept(world);
        }
    }

    /** @return simulation time in seconds after the last step */
    double timeS() {
        return timeS;
    }

    /** @return the laser's configuration (immutable; no lock needed) */
    LaserConfig laserConfig() {
        return world.laserConfig();
    }

    /** @return the robot's configuration (immutable; no lock needed) */
    RobotConfig robotConfig() {
        return world.robotConfig();
    }
}
