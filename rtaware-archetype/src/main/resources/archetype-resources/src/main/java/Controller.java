package ${package};

import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.time.SystemClock;
import java.time.Duration;

/**
 * The controller: the range sensor every {@link #SENSOR_PERIOD}, the speed guard every
 * {@link #GUARD_PERIOD}, until Ctrl-C; then the summary of what time did to them.
 * {@code mvn -q compile exec:java} runs it.
 */
public final class Controller {
    /** How often the sensor publishes a range. */
    public static final Duration SENSOR_PERIOD = Duration.ofMillis(20);
    /** How often the guard decides the speed. */
    public static final Duration GUARD_PERIOD = Duration.ofMillis(50);

    private Controller() {
    }

    /**
     * Runs the controller until Ctrl-C, then prints the summary.
     *
     * @param args none
     */
    public static void main(String[] args) {
        // A stand-in for a sensor: an obstacle that comes as near as 0.2 m and goes back to 1.8 m.
        RangeSensor sensor = new RangeSensor(nowNs -> 1.0 + 0.8 * Math.sin(nowNs * 1e-9));
        Monitor monitor = Monitor.builder(new SystemClock())
                .task("sensor", Schedule.periodic(SENSOR_PERIOD), sensor)
                .task("guard", Schedule.periodic(GUARD_PERIOD), new SpeedGuard())
                .build();               // the data graph is checked here, buffers are allocated

        // Starts the tasks, stops them on Ctrl-C, waits for the end and prints the summary.
        monitor.runUntilStopped();
    }
}
