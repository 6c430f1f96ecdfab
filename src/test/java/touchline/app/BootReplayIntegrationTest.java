package touchline.app;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.model.RobotSnapshot;
import touchline.proto.Fumanoid;
import touchline.security.Authenticity;
import touchline.security.CounterSource;
import touchline.security.KeyDir;
import touchline.security.LinkSecurity;
import touchline.security.RobotBoots;
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
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 35, items 1 and 2, on loopback with the real firmware binary and a keyed console: captures
 * of a robot's earlier boot, played again by a stranger, neither displace the robot's current boot
 * at the console (it stays online and verified, its commands go to its own address) nor act on the
 * robot after its reboot (the console's requests are bound to the robot's boot).
 */
@Tag("integration")
class BootReplayIntegrationTest {

    @TempDir
    Path tmp;

    private final List<Envelope> seen = new CopyOnWriteArrayList<>();

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }

    private KeyDir keys() throws Exception {
        KeyDir dir = new KeyDir(tmp.resolve("keys"));
        dir.create(false, new SecureRandom(), Instant.now());
        return dir;
    }

    private Console console(KeyDir keys) throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))
                .withSecurity(LinkSecurity.with(keys.teamKey(), new CounterSource(System::currentTimeMillis,
                        keys.counterStore()), new RobotBoots(keys.bootStore())));
        Console console = new Console(config);
        console.field().bus().subscribe(seen::add);
        return console.start();
    }

    private RobotProcess robot3(KeyDir keys, int consolePort) {
        return RobotProcess.robot(3, consolePort, "--team-key", keys.file(KeyDir.TEAM_KEY).toString(),
                "--boot-file", tmp.resolve("robot-3.boot").toString());
    }

    private static boolean verifiedAndListed(Console console) {
        return console.field().options().options(3).listReceived()
                && console.field().robots().robot(3).map(r -> r.auth().state() == Authenticity.VERIFIED).orElse(false);
    }

    private static boolean enabledOnRobot(Console console, String option) {
        return console.field().options().options(3).options().stream()
                .anyMatch(o -> o.name().equals(option) && o.enabledOnRobot());
    }

    private static Fumanoid.AuthCounters atRobot(Console console) {
        Fumanoid.AuthCounters c = console.field().robots().robot(3).map(r -> r.auth().atRobot()).orElse(null);
        return c == null ? Fumanoid.AuthCounters.getDefaultInstance() : c;
    }

    @Test
    void capturesOfAnEarlierBootNeitherLockTheRobotOutNorMoveItsAddress() throws Exception {
        KeyDir keys = keys();
        // the earlier boot, heard by a stranger's socket (the console is not running yet)
        List<byte[]> capture = new ArrayList<>();
        try (java.net.DatagramSocket sniffer = new java.net.DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
             RobotProcess earlier = robot3(keys, sniffer.getLocalPort()).start()) {
            sniffer.setSoTimeout(10_000); // a bound, not a pause: the robot sends a Status every 200 ms
            while (capture.size() < 6) {
                java.net.DatagramPacket p = new java.net.DatagramPacket(new byte[2048], 2048);
                sniffer.receive(p);
                capture.add(java.util.Arrays.copyOf(p.getData(), p.getLength()));
            }
        }
        try (Console console = console(keys);
             RobotProcess robot = robot3(keys, console.field().port()).start();
             DatagramChannel attacker = DatagramChannel.open().bind(new InetSocketAddress("127.0.0.1", 0))) {
            Await.until("robot 3 verified with its option list", () -> verifiedAndListed(console));
            InetSocketAddress consoleAddress = new InetSocketAddress("127.0.0.1", console.field().port());
            for (int round = 0; round < 3; round++) {
                for (byte[] d : capture) {
                    attacker.send(ByteBuffer.wrap(d), consoleAddress);
                }
            }
            Await.until("every replayed datagram refused",
                    () -> console.field().robots().robot(3).map(r -> r.auth().forged() >= 3L * capture.size()).orElse(false));
            RobotSnapshot r = console.field().robots().robot(3).orElseThrow();
            assertTrue(r.auth().lastForgery().contains("earlier boot"), r.auth().lastForgery());
            long verifiedBefore = r.auth().verified();
            Await.until("the robot's current datagrams still verified", () -> console.field().robots().robot(3)
                    .map(x -> x.auth().verified() > verifiedBefore + 2).orElse(false));
            r = console.field().robots().robot(3).orElseThrow();
            assertTrue(r.online(), "robot 3 stays online");
            assertEquals(Authenticity.VERIFIED, r.auth().state());

            // commands still reach the real robot, and nothing reaches the stranger
            assertTrue(console.optionSwitches().set(3, "demo.text", true).isSent());
            Await.until("demo.text on at the robot", () -> enabledOnRobot(console, "demo.text"));
            assertTrue(seen.stream().filter(e -> e.direction() == Direction.OUT && e.robotId() == 3)
                    .allMatch(e -> e.peer().getPort() == robot.port()), "every command went to the robot's port");
            attacker.configureBlocking(false);
            assertNull(attacker.receive(ByteBuffer.allocate(2048)), "the stranger got no command");
        }
    }

    @Test
    void theConsolesRequestsOfAnEarlierBootDoNothingAfterTheRobotRebooted() throws Exception {
        KeyDir keys = keys();
        try (Console console = console(keys);
             DatagramChannel attacker = DatagramChannel.open()) {
            byte[] capture;
            try (RobotProcess earlier = robot3(keys, console.field().port()).start()) {
                Await.until("robot 3 verified with its option list", () -> verifiedAndListed(console));
                assertTrue(console.optionSwitches().set(3, "demo.plotter", true).isSent());
                Await.until("demo.plotter on", () -> enabledOnRobot(console, "demo.plotter"));
                capture = seen.stream().filter(e -> e.direction() == Direction.OUT
                        && e.kind().equals("debugOptionRequest")).reduce((a, b) -> b).orElseThrow().raw();
                assertTrue(console.optionSwitches().set(3, "demo.plotter", false).isSent());
                Await.until("demo.plotter off", () -> !enabledOnRobot(console, "demo.plotter"));
            }
            int bootBefore = console.field().robots().robot(3).orElseThrow().auth().atRobot().getBootId();
            try (RobotProcess rebooted = robot3(keys, console.field().port()).start()) {
                Await.until("the robot's next boot verified", () -> verifiedAndListed(console)
                        && atRobot(console).getBootId() != bootBefore);
                attacker.send(ByteBuffer.wrap(capture), new InetSocketAddress("127.0.0.1", rebooted.port()));
                Await.until("the robot refused the capture", () -> atRobot(console).getBadTag() >= 1);
                // the robot handles datagrams in order: once a real request's answer is back, the
                // capture would already have acted. It did not.
                assertTrue(console.optionSwitches().set(3, "demo.table", true).isSent());
                Await.until("demo.table on", () -> enabledOnRobot(console, "demo.table"));
                assertFalse(enabledOnRobot(console, "demo.plotter"), "the capture of the earlier boot switched nothing");
                assertTrue(Integer.compareUnsigned(atRobot(console).getBootId(), bootBefore) > 0,
                        "the boot number went up");
            }
        }
    }
}
