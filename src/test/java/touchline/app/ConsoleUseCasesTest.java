package touchline.app;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.transport.MicrosClock;
import touchline.transport.ReliableSession;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The use cases the faces call instead of the transports (issue #11): the port, the transport's
 * counts, waiting for a robot, the reliable stream. A real console on loopback, a plain UDP
 * socket standing in for the robot.
 */
@Tag("integration")
class ConsoleUseCasesTest {

    private static ConsoleConfig loopback() {
        return ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
    }

    private static void sendStatus(DatagramSocket robot, int id, int port) throws Exception {
        byte[] d = new FrameCodec().encode(Framing.LENGTH_PREFIX, Fumanoid.Message.newBuilder().setRobotID(id)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
        robot.send(new DatagramPacket(d, d.length, InetAddress.getLoopbackAddress(), port));
    }

    private static int freePort() throws Exception {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            return s.getLocalPort();
        }
    }

    /**
     * `touchline options` and `touchline nao` wait out the first listen through this one use case:
     * without a GameController port it returns at once; with one, not before match mode's first
     * listen is over (so a request is not held for it) and the port has been open the time asked.
     */
    @Test
    void aOneShotCommandWaitsOutTheFirstListenForAGameController() throws Exception {
        try (Console quiet = new Console(loopback()).start()) {
            quiet.referee().awaitFirstListen(60_000, Duration.ofSeconds(60));
            assertFalse(quiet.referee().matchMode().listeningFirst(), "no GameController port: nothing to wait for");
        }
        ConsoleConfig withGc = loopback().withGameControllerPort(freePort());
        try (Console console = new Console(withGc).start()) {
            long opened = console.field().clock().nowMicros();
            console.referee().awaitFirstListen(900, Duration.ofSeconds(60));
            assertFalse(console.referee().matchMode().listeningFirst(), "the first listen is over");
            assertTrue(console.field().clock().nowMicros() - opened >= 900_000 - 50_000,
                    "listened at least the time asked (from when the port opened, just before " + opened + ")");
            assertFalse(console.referee().matchMode().playIsOn());
        }
    }

    @Test
    void waitsForARobotHeardOnThePortItNamesAndCountsItsDatagram() throws Exception {
        try (Console console = new Console(loopback()).start();
             DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            assertEquals(console.field().udp().localPort(), console.field().port());
            assertEquals(0, console.field().transportCounts().datagramsIn());
            sendStatus(robot, 6, console.field().port());
            var seen = console.field().waitForRobot(6, Duration.ofSeconds(10));
            assertTrue(seen.isPresent(), "robot 6 was heard");
            assertEquals(robot.getLocalPort(), seen.get().address().getPort());
            assertEquals(1, console.field().transportCounts().datagramsIn());
            assertFalse(console.field().transportDescription().isBlank());

            ReliableSession stream = console.field().openStream(seen.get().address());
            assertSame(stream, console.field().openStream(seen.get().address()), "one session per peer");
            stream.offer(new byte[]{1, 2, 3});
            robot.setSoTimeout(10_000);
            boolean segment = false;
            for (int i = 0; i < 5 && !segment; i++) { // the option-list request to a new robot may come first
                DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
                robot.receive(p);
                assertEquals(console.field().port(), p.getPort(), "sent from the console's socket");
                byte[] got = java.util.Arrays.copyOf(p.getData(), p.getLength());
                segment = got.length > 3 && java.util.Arrays.equals(new byte[]{1, 2, 3},
                        java.util.Arrays.copyOfRange(got, got.length - 3, got.length));
            }
            assertTrue(segment, "the stream's first segment reached the robot");
        }
    }

    @Test
    void aRobotNeverHeardIsNotWaitedForBeyondTheTimeoutByTheConsolesClock() throws Exception {
        // a clock that moves 1 s at each reading: the 5 s timeout passes after a few polls, whatever the wall clock does
        AtomicLong micros = new AtomicLong(1_000_000_000L);
        MicrosClock clock = () -> micros.getAndAdd(1_000_000L);
        try (Console console = new Console(loopback(), clock).start()) {
            long before = micros.get();
            assertTrue(console.field().waitForRobot(9, Duration.ofSeconds(5)).isEmpty());
            assertTrue(micros.get() - before >= 5_000_000L, "it waited the timeout by the console's clock");
        }
    }

    @Test
    void aRobotAlreadyHeardIsGivenAtOnceEvenWithNoTimeLeft() throws Exception {
        AtomicLong micros = new AtomicLong(1_000_000_000L); // stands still
        try (Console console = new Console(loopback(), micros::get).start();
             DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            sendStatus(robot, 6, console.field().port());
            touchline.testing.Await.until("robot 6 in the registry", () -> console.field().robots().robot(6).isPresent());
            var seen = console.field().waitForRobot(6, Duration.ZERO);
            assertTrue(seen.isPresent(), "a robot heard before the wait is there");
            assertEquals(robot.getLocalPort(), seen.get().address().getPort());
        }
    }

    @Test
    void aRobotHeardDuringTheWaitEndsItThoughTheConsolesClockStandsStill() throws Exception {
        // the clock never reaches the deadline: only the robot's coming can end the wait
        AtomicLong micros = new AtomicLong(1_000_000_000L);
        ExecutorService waiter = Executors.newSingleThreadExecutor();
        try (Console console = new Console(loopback(), micros::get).start();
             DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            Future<Optional<touchline.model.RobotSnapshot>> seen =
                    waiter.submit(() -> console.field().waitForRobot(7, Duration.ofHours(1)));
            sendStatus(robot, 7, console.field().port());
            var got = seen.get(30, TimeUnit.SECONDS);
            assertTrue(got.isPresent(), "robot 7 was heard");
            assertEquals(robot.getLocalPort(), got.get().address().getPort());
        } finally {
            waiter.shutdownNow();
        }
    }

    @Test
    void aWaitEndsEmptyWhenTheConsolesClockPassesTheDeadline() throws Exception {
        AtomicLong micros = new AtomicLong(1_000_000_000L);
        CountDownLatch deadlineTaken = new CountDownLatch(1);
        MicrosClock clock = () -> {
            long now = micros.get();
            if (Thread.currentThread().getName().equals("robot-waiter")) {
                deadlineTaken.countDown(); // the waiter's first reading (taken) sets its deadline
            }
            return now;
        };
        ExecutorService waiter = Executors.newSingleThreadExecutor(r -> new Thread(r, "robot-waiter"));
        try (Console console = new Console(loopback(), clock).start()) {
            Future<Optional<touchline.model.RobotSnapshot>> seen =
                    waiter.submit(() -> console.field().waitForRobot(9, Duration.ofSeconds(5)));
            assertTrue(deadlineTaken.await(30, TimeUnit.SECONDS), "the wait began");
            micros.addAndGet(5_000_000L); // now at the deadline, by the console's clock only
            assertTrue(seen.get(30, TimeUnit.SECONDS).isEmpty(), "no robot 9; the wait ended at the deadline");
        } finally {
            waiter.shutdownNow();
        }
    }
}
