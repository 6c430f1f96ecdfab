package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.ReturnPacket;
import touchline.transport.Envelope;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The console as a monitor of an HSL GameController, played by a loopback socket. */
class GcMonitorTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);

    private static final ReturnPacket.V4 UPRIGHT = new ReturnPacket.V4(1, 5, 0, 1000f, -500f, 1.5f, 0.5f, 250f, 30f);
    private static final ReturnPacket.V4 FALLEN = new ReturnPacket.V4(20, 14, 1, 0f, 0f, 0f, -1f, 0f, 0f);
    private static final ReturnPacket.V4 NAN_POSE = new ReturnPacket.V4(20, 14, 0, Float.NaN, 0f, 0f, -1f, 0f, 0f);

    private static byte[] forwarded(int a, int b, int c, int d, ReturnPacket.V4 packet) {
        return new ForwardedReturnPacket(new byte[]{(byte) a, (byte) b, (byte) c, (byte) d}, packet).encode();
    }

    @Test
    void registersAndShowsTheRobotsAsTheGameControllerSeesThem() throws Exception {
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        MonitorRegistrations registrations = new MonitorRegistrations();
        AtomicLong now = new AtomicLong(1000);
        try (LoopbackReceiver gameController = new LoopbackReceiver();
             GcMonitor monitor = new GcMonitor(gameController.address(), ANY_LOOPBACK_PORT, registrations,
                     envelopes::add, () -> now.get() * 1000).start()) {
            assertTrue(registrations.isRegisteredWith(InetAddress.getLoopbackAddress()));
            LoopbackReceiver.Received request = gameController.receive(2000);
            assertNotNull(request, "monitor request sent");
            assertArrayEquals(new byte[]{'R', 'G', 'T', 'r', 0}, request.data());

            gameController.send(forwarded(10, 0, 5, 12, UPRIGHT), monitor.forwardAddress());
            gameController.send(forwarded(0, 0, 0, 0, FALLEN), monitor.forwardAddress());
            gameController.send(forwarded(10, 0, 14, 20, NAN_POSE), monitor.forwardAddress());
            gameController.send(forwarded(10, 0, 14, 20, FALLEN), monitor.forwardAddress());
            Await.until(() -> monitor.robots().size() == 2, 2000, "two robots seen through the GameController");
            Await.until(() -> monitor.badPackets().total() == 2, 2000, "two bad forwarded packets counted");

            GcMonitor.Seen upright = monitor.robots().get(new RobotLiveness.RobotKey(5, 1));
            assertEquals("10.0.5.12", upright.robotHost());
            assertEquals(0, upright.packet().fallen());
            assertEquals(1000f, upright.packet().poseX());
            assertEquals(250f, upright.packet().ballX());
            GcMonitor.Seen fallen = monitor.robots().get(new RobotLiveness.RobotKey(14, 20));
            assertEquals("10.0.14.20", fallen.robotHost(), "the bad prefix did not overwrite the good one");
            assertEquals(1, fallen.packet().fallen());
            assertTrue(envelopes.stream().anyMatch(e -> e.error() != null && e.error().contains("not a robot's unicast")));
            assertTrue(envelopes.stream().anyMatch(e -> e.error() != null && e.error().contains("invalid pose")));

            assertEquals(RobotLiveness.Status.ONLINE, monitor.liveness().status(5, 1, now.get()));
            now.set(3500);
            assertEquals(RobotLiveness.Status.LATE, monitor.liveness().status(5, 1, now.get()));
            now.set(5500);
            assertEquals(RobotLiveness.Status.OFFLINE, monitor.liveness().status(5, 1, now.get()));
        }
    }

    @Test
    void forwardedPacketsAreBelievedOnlyFromTheMonitoredGameController() throws Exception {
        try (LoopbackReceiver gameController = new LoopbackReceiver();
             java.net.DatagramSocket stranger = new java.net.DatagramSocket(new InetSocketAddress("127.0.0.2", 0));
             GcMonitor monitor = new GcMonitor(gameController.address(), ANY_LOOPBACK_PORT, new MonitorRegistrations(),
                     e -> { }, () -> 1_000_000).start()) {
            byte[] madeUp = forwarded(10, 0, 14, 20, FALLEN);
            stranger.send(new java.net.DatagramPacket(madeUp, madeUp.length, monitor.forwardAddress()));
            gameController.send(forwarded(10, 0, 5, 12, UPRIGHT), monitor.forwardAddress());
            Await.until(() -> monitor.robots().size() + monitor.badPackets().total() == 2, 2000,
                    "both forwarded packets judged");
            assertEquals(java.util.Set.of(new RobotLiveness.RobotKey(5, 1)), monitor.robots().keySet(),
                    "only the GameController's robot is shown");
            BadPackets.Tally refused = monitor.badPackets().bySource().values().iterator().next();
            assertEquals("not from the monitored GameController 127.0.0.1", refused.lastReason());
        }
    }

    @Test
    void badPacketsFromManySourcesCostOneLineEachUpToTheLimit() throws Exception {
        int sources = BadPackets.MAX_SOURCES + 6;
        List<LoopbackReceiver> senders = new java.util.ArrayList<>();
        try (LoopbackReceiver gameController = new LoopbackReceiver();
             GcMonitor monitor = new GcMonitor(gameController.address(), ANY_LOOPBACK_PORT, new MonitorRegistrations(),
                     e -> { }, () -> 1_000_000).start()) {
            for (int i = 0; i < sources; i++) {
                LoopbackReceiver s = new LoopbackReceiver();
                senders.add(s);
                s.send(new byte[]{1, 2, 3}, monitor.forwardAddress());
            }
            Await.until(() -> monitor.badPackets().total() == sources, 2000, "every bad packet counted");
            assertEquals(BadPackets.MAX_SOURCES + 1, monitor.badPackets().bySource().size());
            assertEquals(6, monitor.badPackets().bySource().get(BadPackets.OTHER_SOURCES).count());
            assertEquals(BadPackets.MAX_SOURCES + 1, monitor.describe(1000).size(), "one line a source, one for the rest");
        } finally {
            senders.forEach(LoopbackReceiver::close);
        }
    }
}
