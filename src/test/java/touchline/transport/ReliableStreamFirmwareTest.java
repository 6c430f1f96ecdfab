package touchline.transport;

import touchline.testing.Await;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.protocol.reliable.Mathe;
import touchline.testing.LossyUdpProxy;
import touchline.testing.RobotProcess;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The thesis' acceptance tests between the Java console (Netty handler) and the C firmware
 * (touchline-robot), through a link that drops, duplicates and reorders over 20% of datagrams.
 */
@Tag("integration")
class ReliableStreamFirmwareTest {

    private static final String LOREM = ("Lorem ipsum dolor sit amet, consectetur adipiscing elit, sed do eiusmod "
            + "tempor incididunt ut labore et dolore magna aliqua. Ut enim ad minim veniam, quis nostrud exercitation.\n")
            .repeat(40);

    @BeforeEach
    void needsBinary() {
        touchline.testing.Requirement.robotSide("touchline-robot");
    }


    private Console console() throws InterruptedException {
        return new Console(ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
    }

    @Test
    void loremIpsumFromConsoleToFirmware() throws Exception {
        try (Console console = console();
             LossyUdpProxy link = new LossyUdpProxy(new java.net.InetSocketAddress("127.0.0.1", console.field().port()), 0.15, 0.05, 0.05, 11)) {
            ReliableSession session = console.field().openStream(link.consoleSide());
            try (RobotProcess robot = RobotProcess.robot(4, link.robotSide().getPort(), "--reliable-print").start()) {
                byte[] text = LOREM.getBytes(StandardCharsets.US_ASCII);
                for (int off = 0; off < text.length; off += 300) {
                    session.offer(java.util.Arrays.copyOfRange(text, off, Math.min(text.length, off + 300)));
                }
                Await.until("the robot printed the whole text", 60_000, () -> robot.stdout().contains(LOREM));
                assertTrue(robot.stdout().contains(LOREM), "whole and in order");
                assertTrue(session.stats().retransmissions() > 0, "the link lost segments");
                assertTrue(link.impaired() >= 0.2 * link.forwarded(), "impairment " + link.impaired() + " of " + link.forwarded());
            }
        }
    }

    @Test
    void loremIpsumFromFirmwareToConsole(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("lorem.txt"), LOREM);
        try (Console console = console();
             LossyUdpProxy link = new LossyUdpProxy(new java.net.InetSocketAddress("127.0.0.1", console.field().port()), 0.15, 0.05, 0.05, 12)) {
            ReliableSession session = console.field().openStream(link.consoleSide());
            ByteArrayOutputStream got = new ByteArrayOutputStream();
            session.onReceive(p -> {
                synchronized (got) {
                    got.writeBytes(p);
                }
            });
            try (RobotProcess robot = RobotProcess.robot(5, link.robotSide().getPort(), "--reliable-send", file.toString()).start()) {
                Await.until("the console received the whole text", 60_000, () -> {
                    synchronized (got) {
                        return got.size() >= LOREM.length();
                    }
                });
                synchronized (got) {
                    assertEquals(LOREM, got.toString(StandardCharsets.US_ASCII));
                }
                assertTrue(session.stats().duplicates() + link.impaired() > 0);
            }
        }
    }

    @Test
    void matheBothSidesAtOnce() throws Exception {
        int operands = 150;
        try (Console console = console();
             LossyUdpProxy link = new LossyUdpProxy(new java.net.InetSocketAddress("127.0.0.1", console.field().port()), 0.15, 0.05, 0.05, 13)) {
            ReliableSession session = console.field().openStream(link.consoleSide());
            Mathe mathe = new Mathe(operands, 99);
            session.onReceive(p -> {
                synchronized (mathe) {
                    mathe.receive(p);
                }
            });
            synchronized (mathe) {
                for (byte[] m = mathe.next(); m != null; m = mathe.next()) {
                    session.offer(m);
                }
            }
            try (RobotProcess robot = RobotProcess.robot(6, link.robotSide().getPort(), "--mathe", Integer.toString(operands)).start()) {
                Await.until("both sides finished", 90_000, () -> {
                    synchronized (mathe) {
                        return mathe.peerEnded() && session.idle() && robot.stdout().contains("MATHE ");
                    }
                });
                Await.until("the robot's verdict", () -> robot.stdout().contains("MATHE OK") || robot.stdout().contains("MISMATCH"));
                synchronized (mathe) {
                    assertTrue(mathe.agrees(), mathe.summary());
                }
                assertTrue(robot.stdout().contains("MATHE OK"), robot.stdout());
                assertTrue(link.impaired() >= 0.2 * link.forwarded(), "impairment " + link.impaired() + " of " + link.forwarded());
            }
        }
    }
}
