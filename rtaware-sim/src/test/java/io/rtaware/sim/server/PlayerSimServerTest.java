package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.monitor.SteppedThreads;
import io.rtaware.core.time.ManualClock;
import io.rtaware.player.protocol.DeviceAddress;
import io.rtaware.player.protocol.DeviceRequest;
import io.rtaware.player.protocol.DriverInfo;
import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.LaserData;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.PlayerCodec;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.SimulationPose2d;
import io.rtaware.player.protocol.Subtypes;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.robot.msg.Odometry;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioLoader;
import io.rtaware.sim.world.LaserConfig;
import io.rtaware.sim.world.RobotConfig;
import io.rtaware.sim.world.World;
import java.io.EOFException;
import java.io.IOException;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class PlayerSimServerTest {

    static final long MS = 1_000_000L;
    static final Scenario ROOM = ScenarioLoader.load("paper-room");

    private PlayerSimServer server;

    static World world() {
        return new World(ROOM.map().orElseThrow(), ROOM.start(), RobotConfig.KOALA, LaserConfig.URG_04LX, 1L);
    }

    @AfterEach
    void stop() {
        if (server != null) {
            server.close();
        }
    }

    private void stepSeconds(double s) {
        for (int i = 0; i < Math.round(s * 100); i++) {
            server.step(10 * MS);
        }
    }

    static RawClient.Msg subscribe(RawClient c, int interf) throws IOException {
        return c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEV, w -> PlayerCodec.writeDeviceRequest(w,
                new DeviceRequest(DeviceAddress.of(interf, 0), Subtypes.ACCESS_OPEN, "")));
    }

    static void dataMode(RawClient c, int mode) throws IOException {
        RawClient.Msg ack = c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DATAMODE,
                w -> PlayerCodec.writeDataMode(w, mode));
        assertEquals(MessageType.RESP_ACK, ack.header().type());
    }

    @Test
    void handshakeDevicesAndPullRatesInWorldTime() throws IOException {
        server = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        assertTrue(server.port() > 0);
        try (RawClient c = new RawClient(server.port())) {
            assertEquals(PlayerSimServer.VERSION, c.banner);
            dataMode(c, Subtypes.DATAMODE_PULL);
            RawClient.Msg list = c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { });
            List<DeviceAddress> devs = PlayerCodec.readDeviceList(list.reader());
            assertEquals(List.of("simulation:0", "position2d:0", "ranger:0", "laser:0"),
                    devs.stream().map(DeviceAddress::toString).toList());
            assertEquals(16777343L, devs.get(0).host());
            assertEquals(server.port(), devs.get(0).robot());
            RawClient.Msg info = c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DRIVERINFO,
                    w -> PlayerCodec.writeDriverInfo(w, new DriverInfo(DeviceAddress.of(Interfaces.LASER, 0), "")));
            assertEquals("rangertolaser", PlayerCodec.readDriverInfo(info.reader()).driverName());
            RawClient.Msg dev = subscribe(c, Interfaces.POSITION2D);
            DeviceRequest granted = PlayerCodec.readDeviceRequest(dev.reader());
            assertEquals(Subtypes.ACCESS_OPEN, granted.access());
            assertEquals("stage", granted.driverName());
            subscribe(c, Interfaces.LASER);

            stepSeconds(10.0);
            List<RawClient.Msg> round = c.round();
            long odo = round.stream().filter(m -> m.header().interf() == Interfaces.POSITION2D).count();
            long scans = round.stream().filter(m -> m.header().interf() == Interfaces.LASER).count();
            assertEquals(160, odo, "16 Hz of world time");
            assertEquals(100, scans, "10 Hz of world time");
            assertEquals(odo + scans, round.size(), "nothing from unsubscribed ranger");
            RawClient.Msg last = round.get(round.size() - 1);
            assertEquals(10.0, last.header().timestampS(), 1e-9, "timestamps are simulation time");
            LaserData scan = new LaserData(1024);
            PlayerCodec.readLaserScan(last.reader(), scan);
            assertEquals(683, scan.rangeCount);
            assertEquals(Math.toRadians(0.3515625), scan.resolutionRad, 1e-6);
            assertEquals((float) LaserConfig.URG_04LX.maxRangeM(), scan.maxRangeM);
        }
    }

    @Test
    void velocityCommandMovesTheRobotAndSimulationGivesGroundTruth() throws IOException {
        server = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        try (RawClient c = new RawClient(server.port())) {
            dataMode(c, Subtypes.DATAMODE_PULL);
            subscribe(c, Interfaces.POSITION2D);
            c.send(Interfaces.POSITION2D, 0, MessageType.CMD, Subtypes.POSITION2D_CMD_VEL,
                    w -> PlayerCodec.writeVelocityCmd(w, 0.1, 0.0, 0.0, 1));
            // the command is applied by the reader thread; wait for a reply to know it was read
            c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_DEVLIST, w -> { });
            stepSeconds(5.0);
            List<RawClient.Msg> round = c.round();
            Odometry o = new Odometry();
            PlayerCodec.readPosition2dState(round.get(round.size() - 1).reader(), o);
            assertEquals(0.8 + 0.5 - 0.01, o.xM, 0.002);
            assertEquals(0.1, o.vxMps, 1e-9);

            RawClient.Msg pose = c.request(Interfaces.SIMULATION, 0, Subtypes.SIMULATION_REQ_GET_POSE2D,
                    w -> PlayerCodec.writeSimulationPose2d(w, new SimulationPose2d("r0", 0, 0, 0)));
            SimulationPose2d truth = PlayerCodec.readSimulationPose2d(pose.reader());
            assertEquals(server.groundTruth().xM(), truth.xM(), 1e-12);
            assertEquals(o.xM, truth.xM(), 1e-12);

            RawClient.Msg set = c.request(Interfaces.SIMULATION, 0, Subtypes.SIMULATION_REQ_SET_POSE2D,
                    w -> PlayerCodec.writeSimulationPose2d(w, new SimulationPose2d("r0", 2.0, 1.5, 1.0)));
            assertEquals(MessageType.RESP_ACK, set.header().type());
            assertEquals(new Pose2d(2.0, 1.5, 1.0), server.groundTruth());
            RawClient.Msg other = c.request(Interfaces.SIMULATION, 0, Subtypes.SIMULATION_REQ_GET_POSE2D,
                    w -> PlayerCodec.writeSimulationPose2d(w, new SimulationPose2d("r1", 0, 0, 0)));
            assertEquals(MessageType.RESP_NACK, other.header().type());

            RawClient.Msg off = c.request(Interfaces.POSITION2D, 0, Subtypes.POSITION2D_REQ_MOTOR_POWER,
                    w -> PlayerCodec.writeMotorPower(w, false));
            assertEquals(MessageType.RESP_ACK, off.header().type());
            assertTrue(!server.withWorld(World::motorsEnabled));
        }
    }

    @Test
    void missingDevicesAreNackedAndPushHonoursReplaceRule() throws IOException {
        server = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        try (RawClient c = new RawClient(server.port())) {
            dataMode(c, Subtypes.DATAMODE_PUSH);
            RawClient.Msg rule = c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE,
                    w -> PlayerCodec.writeReplaceRule(w, ReplaceRule.latestDataOnly()));
            assertEquals(MessageType.RESP_ACK, rule.header().type());
            RawClient.Msg planner = subscribe(c, Interfaces.PLANNER);
            assertEquals(MessageType.RESP_NACK, planner.header().type());
            assertEquals(Subtypes.ACCESS_ERROR, PlayerCodec.readDeviceRequest(planner.reader()).access());
            RawClient.Msg req = c.request(Interfaces.PLANNER, 0, 1, w -> { });
            assertEquals(MessageType.RESP_NACK, req.header().type(), "divergence: Player stays silent");
            RawClient.Msg unknownSubtype = c.request(Interfaces.LASER, 0, 99, w -> { });
            assertEquals(MessageType.RESP_NACK, unknownSubtype.header().type());

            subscribe(c, Interfaces.RANGER);
            server.step(100 * MS);
            // PUSH: data arrives without asking
            List<Integer> subtypes = new ArrayList<>();
            while (subtypes.size() < 2) {
                RawClient.Msg m = c.read();
                assertEquals(MessageType.DATA, m.header().type());
                assertEquals(Interfaces.RANGER, m.header().interf());
                subtypes.add(m.header().subtype());
            }
            assertEquals(List.of(Subtypes.RANGER_DATA_RANGE, Subtypes.RANGER_DATA_INTNS), subtypes);
        }
    }

    @Test
    void replaceRuleKeepsOnlyTheNewestHeldMessage() throws IOException {
        server = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        try (RawClient c = new RawClient(server.port())) {
            dataMode(c, Subtypes.DATAMODE_PULL);
            c.request(Interfaces.PLAYER, 0, Subtypes.PLAYER_REQ_ADD_REPLACE_RULE,
                    w -> PlayerCodec.writeReplaceRule(w, ReplaceRule.latestDataOnly()));
            subscribe(c, Interfaces.POSITION2D);
            subscribe(c, Interfaces.LASER);
            stepSeconds(3.0);
            List<RawClient.Msg> round = c.round();
            assertEquals(2, round.size());
            assertEquals(3.0, round.get(0).header().timestampS(), 0.07);
        }
    }

    @Test
    void fullQueueDropsOldestAndReportsOverflow() throws IOException {
        server = PlayerSimServer.startManual(world(),
                new ServerConfig("127.0.0.1", 0, "r0", 8, 10 * MS, 1024));
        try (RawClient c = new RawClient(server.port())) {
            dataMode(c, Subtypes.DATAMODE_PULL);
            subscribe(c, Interfaces.POSITION2D);
            stepSeconds(2.0); // 32 odometry messages into a queue of 8
            List<RawClient.Msg> data = new ArrayList<>();
            c.send(Interfaces.PLAYER, 0, MessageType.REQ, Subtypes.PLAYER_REQ_DATA, w -> { });
            c.reply(data);
            RawClient.Msg m;
            while ((m = c.read()).header().type() != MessageType.SYNCH) {
                data.add(m);
            }
            assertEquals(8, data.size());
            assertEquals(2.0, data.get(7).header().timestampS(), 0.07, "the newest are kept");
            assertEquals(Subtypes.PLAYER_SYNCH_OVERFLOW, m.header().subtype());
            assertEquals(24, PlayerCodec.readSynch(m.reader()));
        }
    }

    @Test
    void garbageClientIsDisconnectedWhileOthersGoOn() throws Exception {
        server = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        try (RawClient good = new RawClient(server.port()); RawClient bad = new RawClient(server.port());
             RawClient bad2 = new RawClient(server.port())) {
            dataMode(good, Subtypes.DATAMODE_PULL);
            subscribe(good, Interfaces.POSITION2D);
            byte[] header = new byte[40];
            header[11] = 1; // interf player
            header[19] = 3; // REQ
            header[23] = 1;
            header[36] = 0x7f; // size 2 GiB: refused before allocating
            header[37] = (byte) 0xff;
            bad.sendRaw(header);
            assertThrows(IOException.class, () -> {
                RawClient.Msg m = bad.read();
                throw new AssertionError("expected a disconnect, got " + m.header());
            });
            bad2.send(Interfaces.POSITION2D, 0, MessageType.DATA, 1, w -> { }); // clients do not send DATA
            IOException e = assertThrows(IOException.class, bad2::read);
            assertTrue(e instanceof EOFException || e instanceof SocketException, e.toString());
            stepSeconds(1.0);
            assertEquals(16, good.round().size());
        }
    }

    @Test
    void clockedServerStepsOnTheInjectedClock() throws Exception {
        ManualClock clock = new ManualClock();
        server = PlayerSimServer.start(world(), clock, ServerConfig.defaults(0));
        assertThrows(IllegalStateException.class, () -> server.step(1));
        try (RawClient c = new RawClient(server.port())) {
            dataMode(c, Subtypes.DATAMODE_PULL);
            subscribe(c, Interfaces.POSITION2D);
            // the sim thread takes its first reading when it starts, on a loaded machine perhaps
            // after the advance below (its world would then begin at 2 s): wait for that reading
            assertEquals(0, server.clockOriginNs(), "the world's time 0 is the clock's 0");
            clock.advance(2_000 * MS);
            // the sim thread follows the clock by itself; REQ DATA is answered once data exists
            List<RawClient.Msg> seen = new ArrayList<>();
            double t = 0;
            while (t < 2.0) {
                List<RawClient.Msg> round = c.round();
                seen.addAll(round);
                t = round.get(round.size() - 1).header().timestampS();
            }
            assertEquals(2.0, server.simTimeS(), 1e-9);
            assertEquals(32, seen.size(), "16 Hz over 2 s of world time");
        }
    }

    @Test
    void theSimThreadOnAManualClockTakesEachStepWhenTheClockReachesItsTime() throws Exception {
        ManualClock clock = new ManualClock();
        ServerConfig config = ServerConfig.defaults(0);
        server = PlayerSimServer.start(world(), clock, config);
        SteppedThreads stepped = new SteppedThreads(server.steppingIdle(), clock);

        stepped.runUntil(3 * config.stepPeriodNs() + 1);

        assertEquals(3 * config.stepPeriodNs(), clock.nanos(), "the clock was moved from one step's time to the next");
        assertEquals(3 * config.stepPeriodNs() / 1e9, server.simTimeS(), 1e-12,
                "the world took the three steps due, each when the clock reached it, and waits for the fourth");
    }

    @Test
    void theServersTimestampsLieAtTheClocksOriginPlusTheirValue() throws Exception {
        ManualClock clock = new ManualClock(7_000 * MS);
        server = PlayerSimServer.start(world(), clock, ServerConfig.defaults(0));
        assertEquals(7_000 * MS, server.clockOriginNs(), "world time 0 at the clock's reading when stepping began");
        clock.advance(500 * MS);
        new SteppedThreads(server.steppingIdle(), clock).runUntil(clock.nanos()); // the steps due are taken
        assertEquals(0.5, server.simTimeS(), 1e-12, "the world took the 0.5 s due");
        assertEquals(clock.nanos() - server.clockOriginNs(), Math.round(server.simTimeS() * 1e9),
                "world time = the clock's reading minus the origin, in whole steps");
        PlayerSimServer manual = PlayerSimServer.startManual(world(), ServerConfig.defaults(0));
        try {
            IllegalStateException e = assertThrows(IllegalStateException.class, manual::clockOriginNs);
            assertEquals("a server stepped by hand follows no clock", e.getMessage());
        } finally {
            manual.close();
        }
    }
}
