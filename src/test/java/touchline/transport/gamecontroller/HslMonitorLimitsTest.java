package touchline.transport.gamecontroller;

import org.junit.jupiter.api.Test;
import touchline.app.game.EmbeddedGameController;
import touchline.game.ManualClock;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslGameGoldenTest;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.MonitorRequest;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The embedded HSL GameController's monitor service has limits the official one lacks, seen on
 * loopback (requests from 127.0.0.1 and, where several hosts are needed, 127.0.0.2 and 127.0.0.3):
 * a full table refuses and counts newcomers, a silent monitor expires, a flood of bad requests
 * is told a few times, and the monitors' copy leaves after the robots' packet of its cycle.
 */
class HslMonitorLimitsTest {

    private static final InetSocketAddress ANY_LOOPBACK_PORT = new InetSocketAddress(InetAddress.getLoopbackAddress(), 0);
    private static final int TIMEOUT_MS = 30_000;

    private final List<String> events = new CopyOnWriteArrayList<>();

    private EmbeddedGameController start(LoopbackReceiver robotPort) throws Exception {
        HslGame game = HslGameGoldenTest.goldenGame(20, new ManualClock(0));
        GcConfig config = new GcConfig(GcProfile.HSL20, false, List.of(robotPort.address()), ANY_LOOPBACK_PORT,
                ANY_LOOPBACK_PORT, null, 50, false);
        EmbeddedGameController gc = new EmbeddedGameController(game, config, e -> { }, null,
                new touchline.app.SystemClock());
        gc.addEventListener(events::add);
        return gc;
    }

    private static MonitorService service(int maxMonitors, long leaseMs, List<String> events) throws Exception {
        MonitorService s = new MonitorService(ANY_LOOPBACK_PORT, 1, 1,
                HslGameState20.trueData(), events::add, new touchline.app.SystemClock(), maxMonitors, leaseMs);
        s.start();
        return s;
    }

    private static void request(String host, InetSocketAddress to) throws Exception {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress(host, 0))) {
            byte[] r = new MonitorRequest().encode();
            s.send(new DatagramPacket(r, r.length, to));
        }
    }

    @Test
    void theRobotsPacketOfACycleLeavesBeforeTheMonitorsCopy() throws Exception {
        // one socket is both the robots' port and the monitor's: the order it receives is the send order
        try (LoopbackReceiver shared = new LoopbackReceiver();
             EmbeddedGameController gc = start(shared)) {
            MonitorService service = gc.serveMonitors(ANY_LOOPBACK_PORT, shared.address().getPort(), 1);
            shared.send(new MonitorRequest().encode(), service.requestAddress());
            Await.until(() -> !service.monitors().isEmpty(), TIMEOUT_MS, "monitor registered");
            gc.start();
            List<String> order = new ArrayList<>();
            while (order.stream().filter("RGTD"::equals).count() < 4) {
                LoopbackReceiver.Received r = shared.receive(TIMEOUT_MS);
                assertNotNull(r, "a datagram every cycle");
                order.add(new String(r.data(), 0, 4, StandardCharsets.US_ASCII));
                long robots = order.stream().filter("RGme"::equals).count();
                long truth = order.stream().filter("RGTD"::equals).count();
                assertTrue(truth <= robots, "the monitors' copy went out before the robots' packet: " + order);
            }
        }
    }

    @Test
    void aFullTableRefusesNewcomersAndCountsThem() throws Exception {
        try (MonitorService service = service(2, MonitorService.LEASE_MS, events)) {
            request("127.0.0.1", service.requestAddress());
            request("127.0.0.2", service.requestAddress());
            Await.until(() -> service.monitors().size() == 2, TIMEOUT_MS, "two monitors registered");
            request("127.0.0.3", service.requestAddress());
            request("127.0.0.1", service.requestAddress()); // a registered monitor renews, it is no newcomer
            Await.until(() -> service.stats().refusedFull() == 1, TIMEOUT_MS, "the third host refused");
            assertEquals(Set.of(InetAddress.getByName("127.0.0.1"), InetAddress.getByName("127.0.0.2")),
                    service.monitors());
            assertTrue(service.stats().describe().startsWith("2 of 2 monitors"), service.stats().describe());
            assertTrue(events.contains("monitor request from 127.0.0.3 refused: 2 monitors registered, the most"),
                    events.toString());
        }
    }

    @Test
    void aMonitorThatStopsAskingExpires() throws Exception {
        GameControlData truth = HslGameGoldenTest.goldenGame(20, new ManualClock(0)).trueData();
        java.util.concurrent.atomic.AtomicLong micros = new java.util.concurrent.atomic.AtomicLong(1_000_000);
        try (LoopbackReceiver monitor = new LoopbackReceiver();
             MonitorService service = new MonitorService(ANY_LOOPBACK_PORT, monitor.address().getPort(), 1,
                     HslGameState20.trueData(), events::add, micros::get, MonitorService.MAX_MONITORS, 300)) {
            service.start();
            monitor.send(new MonitorRequest().encode(), service.requestAddress());
            Await.until(() -> service.monitors().size() == 1, TIMEOUT_MS, "monitor registered");
            service.publish(truth);
            assertNotNull(monitor.receive(TIMEOUT_MS), "a registered monitor gets the true state");
            micros.addAndGet(299_000);
            service.publish(truth);
            assertNotNull(monitor.receive(TIMEOUT_MS), "still registered 299 ms after its request");
            assertEquals(0, service.stats().expired());
            micros.addAndGet(1_000); // the monitor asked no more: its lease is over at the next cycle
            service.publish(truth);
            // the count goes up before the event is told (the monitors' thread): wait for both
            Await.until(() -> service.stats().expired() == 1
                    && events.contains("monitor 127.0.0.1 expired: no request for 300 ms"), TIMEOUT_MS,
                    "the silent monitor expired and told");
            assertTrue(service.monitors().isEmpty());
        }
    }

    @Test
    void aFloodOfBadRequestsIsCountedAndToldAtPowersOfTen() throws Exception {
        try (MonitorService service = service(MonitorService.MAX_MONITORS, MonitorService.LEASE_MS, events);
             LoopbackReceiver flooder = new LoopbackReceiver()) {
            for (int i = 0; i < 150; i++) {
                flooder.send(new byte[]{'R', 'G', 'T', 'r', 9}, service.requestAddress());
            }
            Await.until(() -> service.badRequests() == 150, TIMEOUT_MS, "every bad request counted");
            List<String> told = events.stream().filter(e -> e.startsWith("bad monitor request")).toList();
            assertEquals(3, told.size(), told.toString());
            assertTrue(told.get(2).endsWith("(100 so far)"), told.toString());
            assertTrue(service.monitors().isEmpty());
        }
    }
}
