package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;

import static org.junit.jupiter.api.Assertions.*;

class RobotRegistryTest {

    private final long[] now = {5_000_000L};
    private final RobotRegistry registry = new RobotRegistry(() -> now[0]);
    private final InetSocketAddress a = new InetSocketAddress("127.0.0.1", 4001);

    private Envelope status(int id, InetSocketAddress from, String role) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(id).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setTeamID(13).setActiveRole(role).setBatteryPercent(80)
                        .setRobotName("fu" + id).build()).build();
        return new Envelope(now[0], Direction.IN, Channel.FUMANOID, from, id, "status", m, new byte[40], null);
    }

    @Test
    void robotAppearsOnFirstPacketWithItsStatus() {
        registry.accept(status(2, a, "striker"));
        RobotSnapshot r = registry.robot(2).orElseThrow();
        assertTrue(r.online());
        assertEquals("fu2", r.name());
        assertEquals(13, r.teamId());
        assertEquals(80, r.batteryPercent());
        assertEquals("striker", r.role());
        assertEquals(1, r.packets());
        assertEquals(40, r.bytesPerSecond(), 0.001);
    }

    @Test
    void goesOfflineWhenKeepAlivesStopAndStaysListed() {
        registry.accept(status(2, a, "striker"));
        now[0] += 2_900_000; // a game-rate keep-alive (1 s) may be missed twice
        registry.tick();
        assertTrue(registry.robot(2).orElseThrow().online());
        now[0] += 200_000;
        registry.tick();
        assertFalse(registry.robot(2).orElseThrow().online());
        assertEquals(1, registry.robots().size(), "every robot ever seen stays in the list");
    }

    @Test
    void malformedDatagramsAreCountedPerSourceAndAgainstTheRobotAtThatAddress() {
        registry.accept(status(2, a, "striker"));
        registry.accept(new Envelope(now[0], Direction.IN, Channel.FUMANOID, a, Envelope.NO_ROBOT, "malformed", null,
                new byte[3], "truncated header: 3 bytes"));
        SourceSnapshot s = registry.sources().get(0);
        assertEquals(1, s.malformed());
        assertEquals("truncated header: 3 bytes", s.lastError());
        assertEquals(1, registry.robot(2).orElseThrow().malformed());
    }

    @Test
    void robotChangingAddressIsNoted() {
        registry.accept(status(2, a, "striker"));
        InetSocketAddress b = new InetSocketAddress("127.0.0.2", 4001);
        registry.accept(status(2, b, "striker"));
        assertEquals(1, registry.robot(2).orElseThrow().addressChanges());
        assertEquals(b, registry.robot(2).orElseThrow().address());
        assertTrue(registry.notes().get(0).contains("robot 2 moved from"), registry.notes().toString());
    }
}
