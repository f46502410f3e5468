package io.rtaware.live;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import io.rtaware.core.agent.AgentThread;
import io.rtaware.core.agent.ThreadNames;
import io.rtaware.core.conditions.Conditions;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.report.Report;
import io.rtaware.core.report.ReportDocument;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.OccupancyGrid;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;
import org.agrona.concurrent.Agent;
import org.agrona.concurrent.AgentTerminationException;
import org.agrona.concurrent.SleepingMillisIdleStrategy;

/**
 * The live view of one monitor: a {@link LiveServer} plus a publisher thread that builds a
 * snapshot every {@value #PUBLISH_PERIOD_MS} ms of wall time and, for a robot run, a PNG of the
 * occupancy grid at most every {@value #GRID_PERIOD_MS} ms when it changed. The publisher is a
 * background loop ({@link AgentThread}), not a task: it reads counters and copies key values the way any observer
 * may ({@link Monitor#read}), so the task threads never wait for a browser.
 *
 * <p>The task rows carry strip charts of release lateness and execution time over the last
 * minute of world time ({@link TimingSeries}: a listener that copies each cycle record into a
 * preallocated ring on the task's thread, drained by the publisher); the header carries the
 * machine verdict so far ({@link #machine}), refreshed at most every {@value #MACHINE_PERIOD_MS} ms.
 *
 * <p>Use: {@link #start} after the monitor is built and before it starts, {@link #finish}
 * from the termination handler with the report, {@link #close} when the command ends (it
 * lingers as configured). When the options say off, every method does nothing.
 *
 * <p>Thread-safe.
 */
public final class LiveView implements AutoCloseable {

    /** Wall time between snapshots. */
    static final long PUBLISH_PERIOD_MS = 200;
    /** Least wall time between two grid images. */
    static final long GRID_PERIOD_MS = 1_000;
    /** Least wall time between two readings of the machine verdict (each reads the machine's process table). */
    static final long MACHINE_PERIOD_MS = 1_000;

    private final LiveOptions options;
    private final LiveServer server;
    private final Monitor monitor;
    private final RunScene scene;
    private final PrintStream out;
    private final SnapshotBuilder builder;
    private final ObjectMapper mapper;
    /** The publisher loop, started by {@link #start}; null when the view is off. */
    private volatile AgentThread publisher;
    private final OccupancyGrid grid;
    private volatile Supplier<Pose2d> truePose;
    private volatile String truthKind = "odometry";
    private volatile Supplier<Conditions> machine;
    private Conditions machineLatest;
    private long machineWallNs;
    private volatile boolean finished;
    private volatile boolean closed;
    private long gridGeneration;
    private long gridWallNs;
    private int gridPngBytes;

    private LiveView(LiveOptions options, LiveServer server, Monitor monitor, RunScene scene, PrintStream out) {
        this.options = options;
        this.server = server;
        this.monitor = monitor;
        this.scene = scene;
        this.out = out;
        this.builder = monitor == null ? null : new SnapshotBuilder(monitor, scene, monitor.clock().nanos());
        this.mapper = ReportDocument.mapper().disable(SerializationFeature.INDENT_OUTPUT);
        this.grid = scene == null || !monitor.hasKey(scene.keys().map().name()) ? null : scene.keys().map().newBuffer();
    }

    /**
     * Starts the live view of a task set: tasks and keys only (e.g. {@code bench}).
     *
     * @param options where to serve; off gives an inert view
     * @param monitor the monitor to watch, not started yet
     * @param out where the {@code live view: URL} line goes
     * @return the view
     * @throws LiveAddressException if the port is in use or the address is not one of this machine
     * @throws IOException if the page cannot be loaded
     * @throws IllegalStateException if the monitor has started already (the strip charts listen to it)
     */
    public static LiveView start(LiveOptions options, Monitor monitor, PrintStream out) throws IOException {
        return start(options, monitor, null, out);
    }

    /**
     * Starts the live view of a robot run: tasks, keys, the map and the robot.
     *
     * @param options where to serve; off gives an inert view
     * @param monitor the monitor to watch
     * @param scene what to draw besides tasks and keys, or null for tasks and keys only
     * @param out where the {@code live view: URL} line goes
     * @return the view
     * @throws LiveAddressException if the port is in use or the address is not one of this machine
     * @throws IOException if the page cannot be loaded
     * @throws IllegalStateException if the monitor has started already (the strip charts listen to it)
     */
    public static LiveView start(LiveOptions options, Monitor monitor, RunScene scene, PrintStream out)
            throws IOException {
        if (!options.enabled()) {
            return new LiveView(options, null, null, null, out);
        }
        Objects.requireNonNull(monitor, "monitor");
        InetAddress address;
        LiveServer server;
        try {
            address = InetAddress.getByName(options.bindAddress());
            server = new LiveServer(new InetSocketAddress(address, options.port()), page());
        } catch (UnknownHostException e) {
            throw new LiveAddressException("--live-bind: cannot resolve '" + options.bindAddress() + "' to an address of this machine");
        } catch (BindException e) {
            throw new LiveAddressException("cannot serve the live view on " + options.bindAddress() + ":" + options.port() + ": "
                    + e.getMessage() + " (--live-port in use, or --live-bind not an address of this machine)");
        }
        LiveView view = new LiveView(options, server, monitor, scene, out);
        try {
            monitor.addListener(view.builder.series());
        } catch (IllegalStateException e) {
            server.close();
            throw e;
        }
        if (scene != null && scene.world() != null) {
            server.putResource("/world.png", "image/png", MapImages.world(scene.world()));
        }
        view.publishOnce();
        view.publisher = AgentThread.start(view.new Publisher(), new SleepingMillisIdleStrategy(PUBLISH_PERIOD_MS),
                // A bug in the view must not end the run: say it once; the publisher has stopped.
                error -> out.println("live view: stopped publishing: "
                        + (error instanceof AgentTerminationException && error.getCause() != null ? error.getCause() : error)));
        String host = address.isAnyLocalAddress() ? LiveOptions.LOOPBACK : address.getHostAddress();
        if (host.contains(":")) {
            host = "[" + host + "]";
        }
        out.println("live view: http://" + host + ":" + server.port() + "/");
        out.flush();
        return view;
    }

    private static byte[] page() throws IOException {
        try (InputStream in = LiveView.class.getResourceAsStream("live.html")) {
            if (in == null) {
                throw new IOException("live.html is missing from the class path");
            }
            return in.readAllBytes();
        }
    }

    /** @return the port served on, or -1 when off */
    public int port() {
        return server == null ? -1 : server.port();
    }

    /**
     * Names the source of the robot's true pose, once it exists (the referee starts with the run).
     *
     * @param pose returns the latest true pose or null; called from the publisher thread
     * @param kind {@code ground_truth} or {@code odometry}
     */
    public void truePose(Supplier<Pose2d> pose, String kind) {
        this.truthKind = Objects.requireNonNull(kind, "kind");
        this.truePose = Objects.requireNonNull(pose, "pose");
    }

    /**
     * Names the run's machine conditions so far, shown in the page's header while the run goes
     * and in the final page ({@code machine}: the verdict and its reasons).
     *
     * @param conditions returns the conditions from the run's start to now (after the run, the
     *     final ones), or null before the measurement starts; called from the publisher thread at most every {@value #MACHINE_PERIOD_MS} ms
     */
    public void machine(Supplier<Conditions> conditions) {
        this.machine = Objects.requireNonNull(conditions, "conditions");
    }

    /**
     * Publishes the final snapshot: the last live figures plus the report (and the run's own
     * section), which the page shows as the summary and keeps showing on reload.
     *
     * @param report the termination report
     * @param runSection the run's section of the report (serialized as {@code final.run}), or null
     */
    public void finish(Report report, Object runSection) {
        if (server == null) {
            return;
        }
        synchronized (this) {
            finished = true;
            ObjectNode snapshot = snapshot("finished");
            ObjectNode end = snapshot.putObject("final");
            end.set("report", mapper.valueToTree(report));
            if (runSection != null) {
                end.set("run", mapper.valueToTree(runSection));
            }
            publish(snapshot);
        }
    }

    /**
     * The publisher: a snapshot every {@value #PUBLISH_PERIOD_MS} ms until finished (then it idles
     * until closed); a fault ends it.
     */
    private final class Publisher implements Agent {
        @Override
        public int doWork() {
            try {
                publishOnce();
            } catch (RuntimeException e) {
                throw new AgentTerminationException(e);
            }
            return 0;
        }

        @Override
        public String roleName() {
            return ThreadNames.LIVE_PUBLISHER; // an observer, off the tasks' per-release path
        }
    }

    private void publishOnce() {
        synchronized (this) {
            if (finished || closed) {
                return;
            }
            publish(snapshot(monitor.isStopping() ? "stopping" : "running"));
        }
    }

    private ObjectNode snapshot(String state) {
        Supplier<Pose2d> pose = truePose;
        ObjectNode snapshot = builder.build(state, pose == null ? null : pose.get(), truthKind);
        putMachine(snapshot);
        if (scene != null) {
            world(snapshot);
        }
        return snapshot;
    }

    /** The machine verdict so far, read again when {@value #MACHINE_PERIOD_MS} ms have passed and at the end. */
    private void putMachine(ObjectNode snapshot) {
        Supplier<Conditions> source = machine;
        if (source == null) {
            return;
        }
        long now = System.nanoTime();
        if (machineLatest == null || finished || now - machineWallNs >= TimeUnit.MILLISECONDS.toNanos(MACHINE_PERIOD_MS)) {
            machineLatest = source.get();
            machineWallNs = now;
        }
        if (machineLatest == null) {
            return; // the measurement has not started yet
        }
        ObjectNode node = snapshot.putObject("machine");
        node.put("verdict", machineLatest.machine());
        ArrayNode reasons = node.putArray("reasons");
        machineLatest.machineReasons().forEach(reasons::add);
        node.put("duration_s", SnapshotBuilder.round(machineLatest.measured().durationS(), 1));
        node.put("rule", machineLatest.rule());
    }

    private void world(ObjectNode snapshot) {
        if (scene.world() != null) {
            ObjectNode w = snapshot.putObject("world");
            w.put("image", "/world.png");
            w.put("origin_x_m", scene.world().originXM);
            w.put("origin_y_m", scene.world().originYM);
            w.put("resolution_m", scene.world().resolutionM);
            w.put("width_cells", scene.world().width());
            w.put("height_cells", scene.world().height());
        }
        if (grid == null) {
            return;
        }
        long now = System.nanoTime();
        if (gridWallNs == 0 || now - gridWallNs >= TimeUnit.MILLISECONDS.toNanos(GRID_PERIOD_MS) || finished) {
            long generation = monitor.read(scene.keys().map(), grid);
            if (generation != gridGeneration && !grid.isEmpty()) {
                byte[] png = MapImages.grid(grid);
                server.putResource("/grid.png", "image/png", png);
                gridGeneration = generation;
                gridPngBytes = png.length;
            }
            gridWallNs = now;
        }
        if (gridGeneration == 0) {
            return;
        }
        ObjectNode g = snapshot.putObject("grid");
        g.put("image", "/grid.png?g=" + gridGeneration);
        g.put("generation", gridGeneration);
        g.put("png_bytes", gridPngBytes);
        g.put("origin_x_m", grid.originXM);
        g.put("origin_y_m", grid.originYM);
        g.put("resolution_m", grid.resolutionM);
        g.put("width_cells", grid.width());
        g.put("height_cells", grid.height());
        g.put("scans_integrated", grid.scansIntegrated);
    }

    private void publish(ObjectNode snapshot) {
        try {
            server.publish(mapper.writeValueAsBytes(snapshot));
        } catch (JsonProcessingException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Keeps serving the final page for the linger time if the run has finished, then stops the
     * publisher and the server. Idempotent.
     */
    @Override
    public void close() {
        if (server == null || closed) {
            return;
        }
        if (finished && options.lingerNs() > 0) {
            out.printf(Locale.ROOT, "live view: run over; serving the final page for %.0f s more (Ctrl-C to stop)%n",
                    options.lingerNs() / 1e9);
            out.flush();
            long until = System.nanoTime() + options.lingerNs();
            for (long left = options.lingerNs(); left > 0; left = until - System.nanoTime()) {
                LockSupport.parkNanos(left);
            }
        }
        closed = true;
        publisher.close();
        server.close();
    }
}
