package io.rtaware.player.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.data.Output;
import io.rtaware.core.monitor.Monitor;
import io.rtaware.core.monitor.StepExecutor;
import io.rtaware.core.task.ErrorPolicy;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.ManualClock;
import io.rtaware.player.ScriptedServer;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.PlayerFrameReader;
import io.rtaware.player.protocol.PlayerHeader;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.player.protocol.VelocityCmd;
import io.rtaware.player.xdr.XdrReader;
import io.rtaware.player.xdr.XdrWriter;
import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.robot.msg.RobotKeys;
import io.rtaware.robot.msg.VelocityCommand;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Semaphore;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Issue 12, "never act on data that cannot be true": the Player data task on the real monitor
 * and step executor (world time is a manual clock), against a scripted server that turns
 * hostile.
 */
@Timeout(60)
class PlayerDataTaskSafetyTest {

    private static final long MS = 1_000_000L;

    /** Commands the robot forward at 0.3 m/s every 100 ms, like a behavior. */
    private static final class Driver implements Task {
        private Output<VelocityCommand> motor;

        @Override
        public void initialize(TaskSetup setup) {
            motor = setup.produce(RobotKeys.MOTOR);
        }

        @Override
        public void execute(long nowNs) {
            motor.value().set(0.3, 0.0);
            motor.publish();
        }
    }

    /** Counts the odometry and scans the data task commits. */
    private static final class Consumer implements Task {
        final AtomicInteger odometry = new AtomicInteger();
        final AtomicInteger scans = new AtomicInteger();
        volatile double lastXM = Double.NaN;
        private io.rtaware.core.data.Input<Odometry> odometryIn;
        private io.rtaware.core.data.Input<LaserScan> laserIn;

        @Override
        public void initialize(TaskSetup setup) {
            odometryIn = setup.consume(RobotKeys.ODOMETRY);
            laserIn = setup.consume(RobotKeys.LASER);
        }

        @Override
        public void execute(long nowNs) {
            if (odometryIn.status() == io.rtaware.core.data.ReadStatus.NEW) {
                odometry.incrementAndGet();
                lastXM = odometryIn.value().xM;
            }
            if (laserIn.status() == io.rtaware.core.data.ReadStatus.NEW) {
                scans.incrementAndGet();
            }
        }
    }

    private static byte[] message(int interf, int type, int subtype, double timeS, java.util.function.Consumer<XdrWriter> body) {
        XdrWriter w = new XdrWriter();
        int at = PlayerCodec.beginMessage(w, DeviceAddress.of(interf, 0), type, subtype, timeS);
        body.accept(w);
        PlayerCodec.endMessage(w, at);
        return w.toByteArray();
    }

    static byte[] odometry(double timeS, double xM) {
        Odometry o = new Odometry();
        o.xM = xM;
        o.yM = 1.0;
        o.vxMps = 0.3;
        return message(Interfaces.POSITION2D, MessageType.DATA, Subtypes.POSITION2D_DATA_STATE, timeS,
                w -> PlayerCodec.writePosition2dState(w, o));
    }

    static byte[] scan(double timeS, float... ranges) {
        LaserData d = new LaserData(ranges.length);
        d.minAngleRad = -1.5f;
        d.maxAngleRad = 1.5f;
        d.resolutionRad = 3.0f / (ranges.length - 1);
        d.maxRangeM = 8.0f;
        System.arraycopy(ranges, 0, d.rangesM, 0, ranges.length);
        d.rangeCount = ranges.length;
        return message(Interfaces.LASER, MessageType.DATA, Subtypes.LASER_DATA_SCAN, timeS,
                w -> PlayerCodec.writeLaserScan(w, d));
    }

    private static byte[] ack(byte[] request) {
        byte[] reply = request.clone();
        reply[19] = MessageType.RESP_ACK;
        return reply;
    }

    private static PlayerHeader header(byte[] msg) throws Exception {
        return PlayerHeader.decode(new XdrReader(msg, 0, msg.length));
    }

    /** 1 ms poll wait, so a cycle of the continuous task costs about a millisecond of wall time. */
    private static PlayerConfig config(int port) {
        PlayerConfig d = PlayerConfig.of("127.0.0.1", port);
        return new PlayerConfig(d.host(), d.port(), d.scanSource(), 0, DataMode.PUSH, 2000, 2000, 60_000, 1, false,
                500, 8000, 500, PlayerFrameReader.DEFAULT_MAX_BODY_BYTES);
    }

    private static Monitor monitor(ManualClock clock, PlayerDataTask player, Consumer consumer) {
        return Monitor.builder(clock)
                .task(new TaskSpec("player", Schedule.continuous(), ErrorPolicy.CONTINUE, player))
                .task(new TaskSpec("driver", Schedule.periodic(100 * MS), ErrorPolicy.CONTINUE, new Driver()))
                .task(new TaskSpec("consumer", Schedule.periodic(10 * MS), ErrorPolicy.CONTINUE, consumer))
                .build();
    }

    @Test
    void aNanPoseThatPersistsForASecondHaltsTheRobotAndIsNeverCommitted() throws Exception {
        List<VelocityCmd> commands = new CopyOnWriteArrayList<>();
        Semaphore maySend = new Semaphore(0); // one true pose at a time, once the consumer saw the last
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            for (int i = 0; i < 4; i++) { // DATAMODE, ADD_REPLACE_RULE, DEV position2d, DEV laser
                conn.send(ack(conn.readMessage()));
            }
            maySend.acquire();
            conn.send(odometry(0.1, 2.0));
            conn.send(scan(0.1, 1f, 2f, 3f));
            maySend.acquire();
            conn.send(odometry(0.2, 2.1));
            maySend.acquire();
            conn.send(odometry(0.3, Double.NaN)); // from here on the pose cannot be true
            int closesAfterStop = 0;
            while (closesAfterStop < 2) {
                byte[] msg = conn.readMessage();
                PlayerHeader h = header(msg);
                if (h.type() == MessageType.CMD) {
                    commands.add(PlayerCodec.readVelocityCmd(new XdrReader(msg, 40, msg.length - 40)));
                    conn.send(odometry(0.4, Double.NaN)); // every command is answered with a NaN pose
                } else {
                    conn.send(ack(msg));
                    if (h.interf() == Interfaces.PLAYER && h.subtype() == Subtypes.PLAYER_REQ_DEV
                            && indexOfFirstStop(commands) >= 0) {
                        closesAfterStop++; // the unsubscriptions after the zero velocity
                    }
                }
            }
        })) {
            ManualClock clock = new ManualClock();
            PlayerDataTask player = new PlayerDataTask(config(server.port()));
            Consumer consumer = new Consumer();
            Monitor monitor = monitor(clock, player, consumer);
            StepExecutor step = monitor.startStepped();
            for (int pose = 1; pose <= 2; pose++) {
                maySend.release();
                stepUntilSamples(step, player, "position2d:0", pose);
                step.runFor(20 * MS); // the consumer's next cycle reads it
            }
            maySend.release(); // the first impossible pose
            long firstRejectionNs = -1;
            for (int i = 0; i < 5000 && player.fault() == null; i++) {
                step.step();
                if (firstRejectionNs < 0 && player.deviceSamples().get("position2d:0").rejectedSamples() > 0) {
                    firstRejectionNs = clock.nanos();
                }
            }
            assertTrue(firstRejectionNs >= 0, "the NaN pose arrived");
            String fault = player.fault();
            assertNotNull(fault, "halted");
            long haltedAtNs = clock.nanos();
            assertTrue(haltedAtNs - firstRejectionNs >= PlayerDataTask.IMPOSSIBLE_DATA_FAULT_AFTER_NS
                    && haltedAtNs - firstRejectionNs <= PlayerDataTask.IMPOSSIBLE_DATA_FAULT_AFTER_NS + 20 * MS,
                    "halted a second of world time after the first rejection: " + (haltedAtNs - firstRejectionNs));
            assertTrue(fault.startsWith("position2d:0 sent only impossible samples for 1.0 s"), fault);
            assertTrue(fault.contains("x = NaN"), fault);
            step.runFor(1000 * MS); // the driver keeps asking for 0.3 m/s
            monitor.stop();
            server.await();

            assertEquals(2, consumer.odometry.get(), "the two true poses, each read once, and no other");
            assertEquals(2.1, consumer.lastXM, 1e-12, "the newest true pose is the last committed one");
            assertEquals(1, monitor.counters("player").errors(), "the halt is counted as the task's error");
            DeviceSamples pose = player.deviceSamples().get("position2d:0");
            assertEquals(pose.samples() - 2, pose.rejectedSamples());
            assertTrue(pose.rejectedSamples() >= 2, "the NaN poses were all rejected: " + pose);
            assertEquals(0, player.deviceSamples().get("laser:0").rejectedSamples());
            int firstZero = indexOfFirstStop(commands);
            assertTrue(firstZero > 0, "drove, then stopped: " + commands);
            for (VelocityCmd c : commands.subList(firstZero, commands.size())) {
                assertEquals(new VelocityCmd(0, 0, 0, 1), c, "never moves again after the halt: " + commands);
            }
            assertEquals(pose.rejectedSamples(), player.stats().rejectedOdometry());
        }
    }

    @Test
    void scansThatStayImpossibleForASecondHaltTheRobotNamingTheLaser() throws Exception {
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            for (int i = 0; i < 4; i++) {
                conn.send(ack(conn.readMessage()));
            }
            conn.send(odometry(0.1, 0.0));
            conn.send(scan(0.1, 1f, 2f, 3f));
            conn.send(scan(0.2)); // a scan of no beams, and no true scan after it
            while (true) {
                byte[] msg;
                try {
                    msg = conn.readMessage();
                } catch (java.io.EOFException closed) {
                    break;
                }
                PlayerHeader h = header(msg);
                if (h.type() == MessageType.REQ) {
                    conn.send(ack(msg));
                } else {
                    conn.send(odometry(0.3, 0.0)); // the pose stays true
                }
            }
        })) {
            ManualClock clock = new ManualClock();
            PlayerDataTask player = new PlayerDataTask(config(server.port()));
            Monitor monitor = monitor(clock, player, new Consumer());
            StepExecutor step = monitor.startStepped();
            for (int i = 0; i < 5000 && player.fault() == null; i++) {
                step.step();
            }
            monitor.stop();
            String fault = player.fault();
            assertNotNull(fault);
            assertTrue(fault.startsWith("laser:0 sent only impossible samples for 1.0 s of world time (1 rejected"),
                    fault);
            assertTrue(fault.contains("the scan has no beams"), fault);
            assertEquals(0, player.deviceSamples().get("position2d:0").rejectedSamples());
        }
    }

    /**
     * Steps until the data task has taken the device's {@code n}th sample (it crosses a loopback
     * socket: a cycle may find none yet); fails after 5000 steps of at most 1 ms of polling each.
     */
    private static void stepUntilSamples(StepExecutor step, PlayerDataTask player, String device, int n) {
        for (int i = 0; i < 5000 && samples(player, device) < n; i++) {
            step.step();
        }
        assertEquals(n, samples(player, device), device + " samples taken");
    }

    private static long samples(PlayerDataTask player, String device) {
        DeviceSamples d = player.deviceSamples().get(device);
        return d == null ? 0 : d.samples();
    }

    private static int indexOfFirstStop(List<VelocityCmd> commands) {
        for (int i = 0; i < commands.size(); i++) {
            if (commands.get(i).vxMps() == 0.0) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void readingsAreKeptInTheirMeaningBeamsThatSayNothingDroppedAndImpossibleScansRejected() throws Exception {
        List<byte[]> scans = List.of(
                scan(0.1, 1f, 2f, 3f),
                scan(0.2, 1f, Float.NaN, 3f), // one beam says nothing: dropped, the scan kept
                scan(0.3, Float.POSITIVE_INFINITY, 2f, 3f), // nothing hit: the maximum
                scan(0.4, 1f, 2f, Float.NEGATIVE_INFINITY), // too close to measure: an obstacle at 0 m
                scan(0.5, 1f, -0.5f, 3f), // below the minimum: an obstacle at 0 m
                scan(0.6, 1f, 2f, 12f), // beyond the 8 m maximum the scan declares: dropped
                scan(0.65, Float.NaN, Float.NaN, Float.NaN), // no usable beam: impossible
                scan(0.05, 1f, 2f, 3f), // earlier than the last true scan: impossible
                scan(0.7, 1f, 2f, 3f));
        Semaphore maySend = new Semaphore(0); // one scan at a time, once the consumer saw the last
        try (ScriptedServer server = new ScriptedServer(conn -> {
            conn.banner();
            for (int i = 0; i < 4; i++) {
                conn.send(ack(conn.readMessage()));
            }
            conn.send(odometry(0.1, 0.0));
            for (byte[] scan : scans) {
                maySend.acquire();
                conn.send(scan);
            }
            while (true) { // acknowledges the unsubscriptions when the test stops the monitor
                byte[] msg;
                try {
                    msg = conn.readMessage();
                } catch (java.io.EOFException closed) {
                    break;
                }
                if (header(msg).type() == MessageType.REQ) {
                    conn.send(ack(msg));
                }
            }
        })) {
            ManualClock clock = new ManualClock();
            PlayerDataTask player = new PlayerDataTask(config(server.port()));
            Consumer consumer = new Consumer();
            Monitor monitor = monitor(clock, player, consumer);
            StepExecutor step = monitor.startStepped();
            for (int n = 1; n <= scans.size(); n++) {
                maySend.release();
                stepUntilSamples(step, player, "laser:0", n);
                step.runFor(20 * MS); // the consumer's next cycle reads what was committed, if anything
            }
            DeviceSamples laser = player.deviceSamples().get("laser:0");
            assertEquals(new DeviceSamples(9, 2, "timestamp = 0.05 s is earlier than the previous sample's 0.6 s", 5),
                    laser, "1 + 1 + 3 beams dropped");
            assertNull(player.fault(), "true scans came in between: no fault");
            assertEquals(7, consumer.scans.get(), "the seven kept scans, each read once, and not the two impossible ones");
            assertEquals(2, player.stats().rejectedScans());
            assertEquals(0, monitor.counters("player").errors());
            monitor.stop();
        }
    }
}
