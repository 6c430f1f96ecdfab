package touchline.app;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.RobotSnapshot;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.security.Authenticity;
import touchline.security.CounterSource;
import touchline.security.KeyDir;
import touchline.security.LinkSecurity;
import touchline.security.MessageTag;
import touchline.security.TeamKey;
import touchline.testing.Await;
import touchline.testing.RobotProcess;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 15 end to end on loopback with the real firmware binary: the console with the team key
 * switches a robot's option; forged option requests (no tag, another key, a replayed capture)
 * change nothing on the robot and its own counters say so; a robot with another key shows as
 * forged in the console, a robot without a key as untagged (and is sent nothing).
 */
@Tag("integration")
class SecureRobotLinkIntegrationTest {

    @TempDir
    Path tmp;

    private final List<Envelope> seen = new CopyOnWriteArrayList<>();

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    private KeyDir keys(String name) throws Exception {
        KeyDir dir = new KeyDir(tmp.resolve(name));
        dir.create(false, new SecureRandom(), Instant.now());
        return dir;
    }

    private Console console(TeamKey key) throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withSecurity(LinkSecurity.with(key, new CounterSource(System::currentTimeMillis, CounterSource.inMemory())));
        Console console = new Console(config);
        console.field().bus().subscribe(seen::add);
        return console.start();
    }

    private long dataFrom(int robot, String option) {
        return seen.stream().filter(e -> e.direction() == Direction.IN && e.robotId() == robot
                && e.message() instanceof Fumanoid.Message m && m.hasExtension(Fumanoid.debugText)
                && m.getExtension(Fumanoid.debugText).getOption().equals(option)).count();
    }

    private static boolean enabledOnRobot(Console console, int robot, String option) {
        return console.field().options().options(robot).options().stream()
                .anyMatch(o -> o.name().equals(option) && o.enabledOnRobot());
    }

    private static Fumanoid.AuthCounters atRobot(Console console, int robot) {
        Fumanoid.AuthCounters c = console.field().robots().robot(robot).map(r -> r.auth().atRobot()).orElse(null);
        return c == null ? Fumanoid.AuthCounters.getDefaultInstance() : c;
    }

    private static byte[] optionRequest(String option, boolean on) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(0)
                .setExtension(Fumanoid.debugOptionRequest,
                        Fumanoid.DebugOptionRequest.newBuilder().setName(option).setEnable(on).build())
                .build();
        return new FrameCodec().encode(Framing.LEGACY, m.toByteArray());
    }

    @Test
    void rightKeySwitchesAnOptionAndForgedRequestsChangeNothing() throws Exception {
        KeyDir team = keys("team");
        KeyDir rival = keys("rival");
        try (Console console = console(team.teamKey());
             RobotProcess robot = RobotProcess.robot(3, console.field().port(), "--team-key",
                     team.file(KeyDir.TEAM_KEY).toString()).start();
             DatagramChannel attacker = DatagramChannel.open()) {
            Await.until("robot 3 verified with its option list", () -> console.field().options().options(3).listReceived()
                    && console.field().robots().robot(3).map(r -> r.auth().state() == Authenticity.VERIFIED).orElse(false));

            // the right key: the option switches on, and off again (the "on" request is kept as a capture)
            assertTrue(console.optionSwitches().set(3, "demo.plotter", true).isSent());
            Await.until("demo.plotter on", () -> enabledOnRobot(console, 3, "demo.plotter"));
            byte[] capture = seen.stream().filter(e -> e.direction() == Direction.OUT
                    && e.kind().equals("debugOptionRequest")).reduce((a, b) -> b).orElseThrow().raw();
            assertEquals('T', capture[capture.length - 32], "what went out carries the trailer");
            assertTrue(console.optionSwitches().set(3, "demo.plotter", false).isSent());
            Await.until("demo.plotter off", () -> !enabledOnRobot(console, 3, "demo.plotter"));

            // forgeries straight to the robot's port: no tag, another team's key, the capture replayed
            InetSocketAddress robotAddress = new InetSocketAddress("127.0.0.1", robot.port());
            attacker.send(ByteBuffer.wrap(optionRequest("demo.text", true)), robotAddress);
            MessageTag rivalTag = new MessageTag(rival.teamKey());
            attacker.send(ByteBuffer.wrap(rivalTag.append(MessageTag.toRobot(0), 3, Long.MAX_VALUE,
                    optionRequest("demo.text", true))), robotAddress);
            attacker.send(ByteBuffer.wrap(capture), robotAddress);
            Await.until("the robot counted all three", () -> {
                Fumanoid.AuthCounters c = atRobot(console, 3);
                return c.getNoTag() >= 1 && c.getWrongKey() >= 1 && c.getReplayed() >= 1;
            });

            // the robot handles datagrams in order: once a real request's answer is back, any
            // forgery would already have acted. It did not.
            assertTrue(console.optionSwitches().set(3, "demo.table", true).isSent());
            Await.until("demo.table on", () -> enabledOnRobot(console, 3, "demo.table"));
            assertFalse(enabledOnRobot(console, 3, "demo.text"), "the forged request switched nothing on");
            assertFalse(enabledOnRobot(console, 3, "demo.plotter"), "the replayed capture switched nothing on");
            assertEquals(0, dataFrom(3, "demo.text"));
            Fumanoid.AuthCounters c = atRobot(console, 3);
            assertEquals(0, c.getBadTag());
            assertTrue(c.getAccepted() >= 3, "the console's own requests were accepted: " + c);
            assertTrue(console.field().robots().robot(3).orElseThrow().auth().describe().contains("replayed"),
                    console.field().robots().robot(3).orElseThrow().auth().describe());
        }
    }

    @Test
    void aRobotWithAnotherKeyIsForgedAndARobotWithoutKeyIsUntagged() throws Exception {
        KeyDir team = keys("team");
        KeyDir rival = keys("rival");
        try (Console console = console(team.teamKey());
             RobotProcess impostor = RobotProcess.robot(4, console.field().port(), "--team-key",
                     rival.file(KeyDir.TEAM_KEY).toString()).start();
             RobotProcess lab = RobotProcess.robot(5, console.field().port()).start()) {
            Await.until("robot 4 forged, robot 5 heard", () ->
                    console.field().robots().robot(4).map(r -> r.auth().state() == Authenticity.FORGED
                            && r.auth().forged() >= 3).orElse(false)
                            && console.field().robots().robot(5).map(r -> r.packets() >= 2).orElse(false));
            RobotSnapshot r4 = console.field().robots().robot(4).orElseThrow();
            assertFalse(r4.online(), "forged data is not taken as the robot's");
            assertEquals(0, r4.packets());
            assertTrue(r4.auth().lastForgery().contains("another team key"), r4.auth().lastForgery());
            assertTrue(r4.auth().lastForgery().startsWith("127.0.0.1:" + impostor.port()), "with its source");
            assertTrue(console.field().transportCounts().forgedIn() >= 3);
            assertFalse(console.field().options().options(4).listReceived(), "nothing of the impostor's reached the model");

            // issue 35: a console with a key shows a robot without one as untagged and sends it nothing
            assertEquals(Authenticity.UNTAGGED, console.field().robots().robot(5).orElseThrow().auth().state());
            touchline.transport.SendResult refused = console.optionSwitches().set(5, "demo.text", true);
            assertFalse(refused.isSent());
            assertTrue(String.valueOf(refused).contains("untagged"), String.valueOf(refused));
            assertTrue(seen.stream().noneMatch(e -> e.direction() == Direction.OUT && e.robotId() == 5),
                    "nothing went to the untagged robot");
            assertTrue(lab.isAlive());
        }
    }

    /** The reliable stream under the key, both ways: segments are tagged and checked like every datagram. */
    @Test
    void theReliableStreamRunsTaggedBothWays() throws Exception {
        KeyDir team = keys("team");
        String line = "a line over the authenticated stream\n".repeat(20);
        Path file = java.nio.file.Files.writeString(tmp.resolve("stream.txt"), line);
        String key = team.file(KeyDir.TEAM_KEY).toString();
        try (Console console = console(team.teamKey());
             RobotProcess printer = RobotProcess.robot(6, console.field().port(), "--team-key", key,
                     "--reliable-print").start();
             RobotProcess sender = RobotProcess.robot(7, console.field().port(), "--team-key", key).start()) {
            Await.until("robots 6 and 7 verified", () -> console.field().robots().robots().stream()
                    .filter(r -> r.auth().state() == Authenticity.VERIFIED).count() == 2);
            touchline.transport.ReliableSession toPrinter = console.field().reliable()
                    .open(new InetSocketAddress("127.0.0.1", printer.port()));
            byte[] bytes = line.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
            for (int off = 0; off < bytes.length; off += 300) {
                toPrinter.offer(java.util.Arrays.copyOfRange(bytes, off, Math.min(bytes.length, off + 300)));
            }
            Await.until("robot 6 printed the whole text", () -> printer.stdout().contains(line));
            // the robot's Status (every 200 ms) reports the segments its verifier accepted
            Await.until("robot 6 reports the segments as authenticated", () -> atRobot(console, 6).getAccepted() > bytes.length / 300);
            assertEquals(0, atRobot(console, 6).getBadTag() + atRobot(console, 6).getNoTag());
        }
        // robot to console: a robot with the key sends a file; the console takes its tagged segments
        try (Console console = console(team.teamKey())) {
            java.io.ByteArrayOutputStream got = new java.io.ByteArrayOutputStream();
            try (RobotProcess sender = RobotProcess.robot(8, console.field().port(), "--team-key", key,
                    "--reliable-send", file.toString()).start()) {
                touchline.transport.ReliableSession fromSender = console.field().reliable()
                        .open(new InetSocketAddress("127.0.0.1", sender.port()));
                fromSender.onReceive(p -> {
                    synchronized (got) {
                        got.writeBytes(p);
                    }
                });
                Await.until("the console received the whole file", () -> {
                    synchronized (got) {
                        return got.size() >= bytes(line).length;
                    }
                });
                synchronized (got) {
                    assertEquals(line, got.toString(java.nio.charset.StandardCharsets.US_ASCII));
                }
                assertEquals(0, console.field().transportCounts().forgedIn(), "no segment was taken for a forgery");
            }
        }
    }

    private static byte[] bytes(String s) {
        return s.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
    }
}
