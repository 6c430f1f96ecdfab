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
        registry.live().accept(status(2, a, "striker"));
        RobotSnapshot r = registry.robot(2).orElseThrow();
        assertTrue(r.online());
        assertEquals("fu2", r.name());
        assertEquals(13, r.teamId());
        assertEquals(80, r.batteryPercent());
        assertEquals("striker", r.role());
        assertEquals(1, r.packets());
        assertEquals(40, r.bytesPerSecond(), 0.001);
    }

    /** The robot's own count of GameController packets it did not believe is shown beside its game state. */
    @Test
    void theOtherGameControllerTheRobotDidNotBelieveIsShownWithItsGameState() {
        registry.live().accept(status(2, a, "striker"));
        assertEquals(0, registry.robot(2).orElseThrow().gcOtherSource());
        assertEquals("", registry.robot(2).orElseThrow().gameStateShown(), "nothing added while the robot counts none");
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(2).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setGameState("PLAYING").setGcOtherSource(1234).build()).build();
        registry.live().accept(new Envelope(now[0], Direction.IN, Channel.FUMANOID, a, 2, "status", m, new byte[40], null));
        RobotSnapshot r = registry.robot(2).orElseThrow();
        assertEquals(1234, r.gcOtherSource());
        assertEquals("PLAYING (1234 from another GameController, not believed)", r.gameStateShown());
    }

    @Test
    void goesOfflineWhenKeepAlivesStopAndStaysListed() {
        registry.live().accept(status(2, a, "striker"));
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
        registry.live().accept(status(2, a, "striker"));
        registry.live().accept(new Envelope(now[0], Direction.IN, Channel.FUMANOID, a, Envelope.NO_ROBOT, "malformed", null,
                new byte[3], "truncated header: 3 bytes"));
        SourceSnapshot s = registry.sources().get(0);
        assertEquals(1, s.malformed());
        assertEquals("truncated header: 3 bytes", s.lastError());
        assertEquals(1, registry.robot(2).orElseThrow().malformed());
    }

    private Envelope withAuth(Envelope e, touchline.security.Authenticity auth) {
        return new Envelope(e.timeMicros(), e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(), e.message(),
                e.raw(), e.error(), e.origin(), auth);
    }

    private Envelope statusWithBoot(int id, int boot, int badTags) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(id).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setTeamID(13).setAuth(Fumanoid.AuthCounters.newBuilder().setAccepted(4)
                        .setBadTag(badTags).setReplayed(1).setBootId(boot)).build()).build();
        return withAuth(new Envelope(now[0], Direction.IN, Channel.FUMANOID, a, id, "status", m, new byte[40], null),
                touchline.security.Authenticity.VERIFIED);
    }

    @Test
    void forgeriesAreShownOnTheRobotTheyClaimWithTheirSourceAndNeverTakenAsItsData() {
        InetSocketAddress attacker = new InetSocketAddress("10.0.0.66", 5000);
        Envelope forged = new Envelope(now[0], Direction.IN, Channel.FUMANOID, attacker, 7, "forged", null, new byte[60],
                "forged: bad tag (claims robot 7)", touchline.transport.Origin.LIVE, touchline.security.Authenticity.FORGED);
        registry.live().accept(forged);
        registry.live().accept(forged);
        RobotSnapshot r = registry.robot(7).orElseThrow();
        assertFalse(r.online());
        assertEquals(0, r.packets());
        assertEquals(touchline.security.Authenticity.FORGED, r.auth().state());
        assertEquals(2, r.auth().forged());
        assertTrue(r.auth().lastForgery().startsWith("10.0.0.66:5000: forged: bad tag"), r.auth().lastForgery());
        assertEquals("forged ×2", r.auth().describe());
        assertEquals(2, registry.notes().size(), "the 1st and 2nd forgery are noted (then the 4th, 8th...)");
        registry.live().accept(forged);
        assertEquals(2, registry.notes().size());
        registry.live().accept(forged);
        assertEquals(3, registry.notes().size());
        assertEquals(1, registry.sources().size(), "counted against its source");
        assertEquals(4, registry.sources().get(0).malformed());
    }

    @Test
    void verifiedDataTheRobotsOwnRejectionsAndARestartAreShown() {
        registry.live().accept(statusWithBoot(3, 0x11, 3));
        RobotSnapshot r = registry.robot(3).orElseThrow();
        assertEquals(touchline.security.Authenticity.VERIFIED, r.auth().state());
        assertEquals("verified; robot rejected: 3 bad tag, 1 replayed", r.auth().describe());
        registry.live().accept(statusWithBoot(3, 0x22, 0));
        assertTrue(registry.notes().contains("robot 3 restarted: counter reset, accepted"), registry.notes().toString());
        registry.live().accept(withAuth(status(5, a, "goalie"), touchline.security.Authenticity.UNVERIFIED));
        assertEquals("unverified", registry.robot(5).orElseThrow().auth().describe());
    }

    @Test
    void robotChangingAddressIsNoted() {
        registry.live().accept(status(2, a, "striker"));
        InetSocketAddress b = new InetSocketAddress("127.0.0.2", 4001);
        registry.live().accept(status(2, b, "striker"));
        assertEquals(1, registry.robot(2).orElseThrow().addressChanges());
        assertEquals(b, registry.robot(2).orElseThrow().address());
        assertTrue(registry.notes().get(0).contains("robot 2 moved from"), registry.notes().toString());
    }
}
