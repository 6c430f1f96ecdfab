package touchline.app.bridges;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.ToFinished;
import touchline.game.ToPlaying;
import touchline.game.ToReady;
import touchline.game.ToSet;
import touchline.model.RobotSnapshot;
import touchline.model.store.FieldPlot;
import touchline.model.store.PlotStore;
import touchline.model.store.TextLine;
import touchline.testing.Await;
import touchline.testing.SimulatedRos2Robot;
import touchline.transport.Channel;
import touchline.transport.Envelope;
import touchline.transport.SendResult;
import touchline.transport.UdpConfig;
import touchline.transport.remote.BridgeStatus;
import touchline.app.game.EmbeddedGameController;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A console with ROS 2 robots behind their Foxglove bridges (the simulated robot: the Python
 * Foxglove SDK, CDR from mcap_ros2's serializer): each is a robot in the Robots table, its
 * messages reach the views by type, the game state it reports drives match mode, and its
 * commands pass the console's send gate.
 */
@Tag("interop")
class RosBridgesIntegrationTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private static int freeLoopbackPort() throws Exception {
        try (DatagramSocket probe = new DatagramSocket(ANY_LOOPBACK_PORT)) {
            return probe.getLocalPort();
        }
    }

    private static Console console(int gcPort) throws InterruptedException {
        return new Console(ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1")
                .withListenPort(0)).withGameControllerPort(gcPort)).start();
    }

    private static Optional<RobotSnapshot> robot(Console c, int id) {
        return c.field().robots().robot(id);
    }

    @Test
    void aBridgedRobotIsARobotOfTheConsoleAndItsMessagesReachTheViewsByType() throws Exception {
        try (Console console = console(0);
             SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--centre", "1.5,-1")) {
            FieldPlot plot = new FieldPlot(console.field().kinds(), PlotStore.DEFAULT_POINTS,
                    console.field().clock().nowMicros());
            console.field().bus().subscribe(plot);
            int id = console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            assertEquals(RosBridges.FIRST_ROBOT, id);
            assertEquals("booster-1", robot(console, id).orElseThrow().name(), "in the table before its first message");

            Await.until("online with a pose, a battery and a game state", () -> robot(console, id)
                    .filter(r -> r.online() && r.hasPosition() && r.batteryPercent() > 0 && !r.gameState().isEmpty())
                    .isPresent());
            RobotSnapshot r = robot(console, id).orElseThrow();
            // the robot walks an ellipse of 1.2 m × 0.8 m around (1.5, -1) m: the field is in mm
            assertTrue(Math.abs(r.x() - 1500) <= 1201 && Math.abs(r.y() + 1000) <= 801, r.x() + ", " + r.y());
            assertTrue(r.batteryPercent() >= 90 && r.batteryPercent() <= 95, "battery " + r.batteryPercent());
            assertEquals("PLAYING", r.gameState());
            assertTrue(r.packetsPerSecond() > 0 && r.bytesPerSecond() > 0);
            assertEquals(0, r.malformed());

            Await.until("its log in the debug console", () -> !console.field().stores().text().since(-1, id, 10).isEmpty());
            TextLine line = console.field().stores().text().since(-1, id, 10).get(0).value();
            assertEquals("booster-1/behavior", line.option());
            assertTrue(line.text().matches("\\[(INFO|WARN)] walking to \\(.*\\)"), line.text());

            Await.until("the pose's fields offered to plot", () -> plot.paths("/pose").contains("/pose:pose.position.x"));
            assertTrue(plot.paths("joint").contains("/joint_states:position[2]"), plot.paths("joint").toString());
            assertTrue(plot.paths("robot_state").contains("/robot_state:temperature"));
            assertTrue(plot.add(id, "/pose:pose.position.x"));
            Await.until("points plotted", () -> plot.snapshot().get(0).count() >= 3);
            assertTrue(plot.csv().startsWith("time_s,robot 1001 /pose:pose.position.x\n"), plot.csv());

            Envelope pose = console.field().stores().network().since(-1, 1000, e -> e.kind().equals("/pose")).get(0).value();
            assertEquals(Channel.BRIDGE, pose.channel());
            assertTrue(pose.ros().line(400).contains("frame_id"), pose.ros().line(400));

            assertTrue(console.referee().matchMode().playIsOn(), "the PLAYING the robot reports is play: " + console.referee().matchMode().notice());
            BridgeStatus s = console.bridges().statuses().get(0);
            assertTrue(s.describe().startsWith("booster-1 ws://127.0.0.1:" + robot.port() + "/ connected (foxglove.sdk.v1, 10 channels"),
                    s.describe());
        }
    }

    private static final String READ_ROS2 = """
            import sys
            from mcap_ros2.reader import read_ros2_messages
            seen = {}
            topics = ["/bridge/1001/pose", "/bridge/1001/rosout", "/bridge/1001/joint_states"]
            for m in read_ros2_messages(sys.argv[1], topics=topics):
                if m.schema.encoding == "ros2msg" and m.channel.topic not in seen:
                    seen[m.channel.topic] = m
            pose = seen["/bridge/1001/pose"].ros_msg
            log = seen["/bridge/1001/rosout"].ros_msg
            print(sorted(seen), seen["/bridge/1001/pose"].channel.message_encoding, pose.header.frame_id,
                  round(pose.pose.orientation.x, 3), log.name)
            """;

    @Test
    void aRecordingKeepsTheBridgedChannelsInTheirOwnEncodingSoMcapRos2ReadsThemDecoded(
            @org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        touchline.testing.PythonMcap.require("mcap_ros2.reader");
        java.nio.file.Path file = dir.resolve("bridged.mcap");
        try (Console console = console(0);
             SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1")) {
            console.recordings().start(file);
            int id = console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            // its log line in the debug console too: the robot's ten channels reach 60 messages before its first log;
            // a second log line: the first one, handed out before it, has reached the recorder too
            Await.until("a pose, two log lines and joints heard", () -> console.field().robots().robot(id)
                    .map(RobotSnapshot::packets).orElse(0L) > 60
                    && console.field().stores().text().since(-1, id, 10).size() >= 2);
            console.recordings().stop();
        }
        String out = touchline.testing.PythonMcap.run(READ_ROS2, file);
        assertEquals("['/bridge/1001/joint_states', '/bridge/1001/pose', '/bridge/1001/rosout'] cdr map 0.0 "
                + "booster-1/behavior", out.trim());
    }

    @Test
    void touchlineReplaysItsOwnRecordingOfABridgedRobotDecodedAsThatRobot(@org.junit.jupiter.api.io.TempDir
                                                                           java.nio.file.Path dir) throws Exception {
        java.nio.file.Path file = dir.resolve("bridged.mcap");
        try (Console console = console(0);
             SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1", "--centre", "1.5,-1")) {
            console.recordings().start(file);
            int id = console.bridges().connect(BridgeAddress.parse("booster-1=" + robot.url()), null);
            Await.until("poses, log lines, joints and the robot state heard", () -> robot(console, id)
                    .filter(r -> r.packets() > 60 && r.hasPosition() && !r.gameState().isEmpty()).isPresent()
                    && !console.field().stores().text().since(-1, id, 10).isEmpty());
            console.recordings().stop();
        }
        List<Envelope> replayed = new java.util.ArrayList<>();
        try (touchline.record.Recording r = touchline.record.Recording.open(file)) {
            touchline.record.Recording.Cursor c = r.cursor(Long.MIN_VALUE);
            for (Envelope e = c.next(); e != null; e = c.next()) {
                replayed.add(e);
            }
            java.io.StringWriter csv = new java.io.StringWriter();
            new touchline.record.ChannelCsvExport(r).write("/bridge/1001/pose", csv);
            assertTrue(csv.toString().lines().findFirst().orElse("").contains("pose.position.x"), csv.toString());
        }
        List<Envelope> poses = replayed.stream().filter(e -> e.kind().equals("/pose")).toList();
        assertFalse(poses.isEmpty());
        for (Envelope pose : poses) {
            assertEquals(Channel.BRIDGE, pose.channel());
            assertEquals(RosBridges.FIRST_ROBOT, pose.robotId(), "the robot it was");
            assertNull(pose.error());
            assertEquals("geometry_msgs/msg/PoseStamped", pose.ros().typeName(), "decoded, not bytes");
            // the ellipse of 1.2 m x 0.8 m around (1.5, -1) m the robot walks
            assertTrue(Math.abs(pose.ros().number("pose.position.x") - 1.5) <= 1.2001, pose.ros().line(200));
        }
        FieldPlot plot = new FieldPlot(new touchline.protocol.MessageKinds(), PlotStore.DEFAULT_POINTS,
                replayed.get(0).timeMicros());
        plot.accept(poses.get(0));
        assertTrue(plot.add(RosBridges.FIRST_ROBOT, "/pose:pose.position.x"), plot.paths("/pose").toString());
        replayed.forEach(plot::accept);
        assertEquals("robot 1001 /pose:pose.position.x", plot.snapshot().get(0).name());
        assertEquals(poses.size(), plot.snapshot().get(0).count());

        // replayed into a console: the bridged robot again, its pose and game state read from its messages
        try (Console viewer = console(0)) {
            touchline.app.Replay replay = viewer.replays().open(file);
            assertTrue(replay.runFor(Long.MAX_VALUE) >= replayed.size());
            RobotSnapshot again = viewer.field().robots().robot(RosBridges.FIRST_ROBOT, touchline.transport.Origin.REPLAY)
                    .orElseThrow();
            assertTrue(again.hasPosition() && Math.abs(again.x() - 1500) <= 1201, again.x() + ", " + again.y());
            assertEquals("PLAYING", again.gameState(), replayed.stream().map(Envelope::kind).distinct().toList() + " " + replayed.stream().filter(e -> e.kind().equals("/robot_state")).findFirst().map(e -> e.error() + " " + (e.ros() == null ? "null" : e.ros().line(300))).orElse("none"));
            assertEquals(0, again.malformed());
        }
    }

    @Test
    void aParameterSetAndAPublishAreHeldDuringPlayingWithTheWordsOfADebugOptionAndGoOutAfter() throws Exception {
        int gcPort = freeLoopbackPort();
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        try (Console console = console(gcPort);
             SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-2", "--game-state", "INITIAL");
             EmbeddedGameController referee = new EmbeddedGameController(game, new GcConfig(GcProfile.HL12, false,
                     List.of(new InetSocketAddress(InetAddress.getLoopbackAddress(), gcPort)), ANY_LOOPBACK_PORT,
                     ANY_LOOPBACK_PORT, null, 500, false), e -> { }, null, new touchline.app.SystemClock())) {
            int id = console.bridges().connect(BridgeAddress.parse("booster-2=" + robot.url()), null);
            Await.until("connected", () -> console.bridges().statuses().get(0).online());
            Await.until("the parameters", () -> console.bridges().refreshParameters(id).isSent()
                    && console.bridges().parameters(id).size() == 3);

            game.perform(new ToReady());
            game.perform(new ToSet());
            game.perform(new ToPlaying());
            referee.start();
            Await.until("match mode from the GameController's PLAYING", () -> console.referee().matchMode().playIsOn());
            SendResult set = console.bridges().setParameter(id, "debug.draw_ball", true);
            SendResult publish = console.bridges().publish(id, "/say", "std_msgs/msg/String", "{\"data\":\"after play\"}");
            assertEquals(SendResult.Outcome.HELD, set.outcome());
            assertEquals(SendResult.Outcome.HELD, publish.outcome());
            // a type the robot advertises (/pose is a ros2msg PoseStamped) goes as CDR: held the same way
            SendResult cdr = console.bridges().publish(id, "/goal_pose", "geometry_msgs/msg/PoseStamped",
                    "{\"header\":{\"frame_id\":\"after play\"}}");
            assertEquals(SendResult.Outcome.HELD, cdr.outcome());
            assertEquals(set.reason(), cdr.reason());
            // the same words as a debug option held in play (the console's gate says them)
            assertEquals("match mode, " + console.referee().matchMode().play() + "; goes out when play stops", set.reason());
            assertEquals(3, console.bridges().held(id).size());
            assertTrue(console.bridges().held(id).contains("/goal_pose (cdr): {\"header\":{\"frame_id\":\"after play\"}}"),
                    console.bridges().held(id).toString());
            assertFalse(robot.heard().contains("client advertised"), robot.heard());

            game.perform(new ToFinished());
            Await.until("play over", () -> !console.referee().matchMode().playIsOn());
            Await.until("the held commands sent", () -> console.bridges().held(id).isEmpty());
            Await.until("the robot heard the publish", () -> robot.heard().contains("{\"data\":\"after play\"}"));
            Await.until("the robot read the CDR publish", () -> robot.heard().contains("(cdr) {\"header\": {\"frame_id\": "
                    + "\"after play\""));
            Await.until("the robot's new value", () -> console.bridges().refreshParameters(id).isSent()
                    && console.bridges().parameters(id).stream().anyMatch(p -> p.name().equals("debug.draw_ball")
                    && Boolean.TRUE.equals(p.value())));
            assertTrue(robot.heard().indexOf("parameter debug.draw_ball set to true") >= 0, robot.heard());
        }
    }
}
