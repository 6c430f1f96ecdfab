package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.model.store.StoreEnvelopes;
import touchline.proto.Fumanoid;
import touchline.transport.Envelope;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The league's debug rule measured per robot, on a manual clock (issue 40). */
class MatchDebugRuleTest {

    private final long[] now = {5_000_000_000L};

    private Envelope status(int robot, String gameState) {
        return StoreEnvelopes.in(now[0], robot, "status", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).setGameState(gameState).build())
                .build());
    }

    /** A digest of robot {@code robot} whose datagram is {@code bytes} long (the rule reads only the size). */
    private Envelope digest(int robot, int bytes) {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.matchDigest,
                Fumanoid.MatchDigest.newBuilder().setStatus(Fumanoid.Status.newBuilder().setGameState("PLAYING")).build())
                .build();
        Envelope e = StoreEnvelopes.in(now[0], robot, "matchDigest", m);
        return new Envelope(e.timeMicros(), e.direction(), e.channel(), e.peer(), robot, e.kind(), m, new byte[bytes],
                null);
    }

    /** {@code seconds} of keep-alives every {@code periodMillis} from both robots. */
    private void run(MatchDebugRule rule, int seconds, long periodMillis, String stateOf1, String stateOf2) {
        for (long t = 0; t < seconds * 1000L; t += periodMillis) {
            rule.accept(status(1, stateOf1));
            rule.accept(status(2, stateOf2));
            now[0] += periodMillis * 1000;
        }
    }

    private MatchDebugRule rule(String profile) throws RuleProfileException {
        return new MatchDebugRule(() -> now[0], MatchDebugRule.Limits.of(RuleProfile.named(profile)));
    }

    @Test
    void aLabKeepAliveDuringPlayIsFlaggedAndTheGameRateIsNot() throws Exception {
        MatchDebugRule lab = rule("hsl-2026");
        run(lab, 12, 200, "PLAYING", "INITIAL");
        List<MatchDebugRule.Reading> broken = lab.broken();
        assertEquals(1, broken.size(), "robot 2 is not in play: its lab rate is allowed");
        assertEquals(1, broken.get(0).robotId());
        assertTrue(broken.get(0).warnings().get(0).startsWith("too often"), broken.get(0).describe());
        assertFalse(lab.reading(2).inPlay());

        MatchDebugRule game = rule("hsl-2026");
        run(game, 12, 1000, "PLAYING", "READY");
        assertTrue(game.broken().isEmpty(), "one a second is the limit, not over it");
        assertEquals(1.0, game.reading(1).perPeriod(), 0.11);
    }

    @Test
    void twoDigestsInOnePeriodAreTooOften() throws Exception {
        MatchDebugRule rule = rule("hsl-2026");
        for (int i = 0; i < 3; i++) {
            rule.accept(digest(4, 300));
            now[0] += 10_000;
            rule.accept(digest(4, 300));
            now[0] += 990_000;
        }
        MatchDebugRule.Reading r = rule.reading(4);
        assertTrue(r.inPlay());
        assertEquals("too often: two datagrams 10 ms apart (one per 1000 ms allowed)", r.warnings().get(0));
    }

    @Test
    void underSplTwoDigestsWithinTwoSecondsAreTooOftenAndOnePerTwoSecondsIsNot() throws Exception {
        MatchDebugRule hslPace = rule("spl-2025");
        assertEquals(2_000_000L, hslPace.limits().periodMicros());
        run(hslPace, 20, 1000, "PLAYING", "PLAYING");
        assertEquals(List.of(1, 2), hslPace.broken().stream().map(MatchDebugRule.Reading::robotId).toList(),
                "one a second is HSL's pace, twice SPL's");
        assertEquals("too often: 2.0 datagrams per period (one per 2000 ms allowed)",
                hslPace.reading(1).warnings().get(0));

        MatchDebugRule close = rule("spl-2025");
        close.accept(digest(4, 300));
        now[0] += 900_000;
        close.accept(digest(4, 300));
        assertEquals(List.of("too often: two datagrams 900 ms apart (one per 2000 ms allowed)"),
                close.reading(4).warnings());

        MatchDebugRule splPace = rule("spl-2025");
        run(splPace, 30, 2000, "PLAYING", "SET");
        assertTrue(splPace.broken().isEmpty(), "one per 2 s is the limit, not over it");
        assertEquals(1.0, splPace.reading(1).perPeriod(), 0.11);
    }

    @Test
    void aDigestOverOneFragmentIsFlaggedUnderTheHslProfileAndOneOverTheSizeUnderAStricterOne() throws Exception {
        MatchDebugRule rule = rule("hsl-2026");
        rule.accept(digest(5, 1472));
        assertEquals(1, rule.reading(5).fragments(), "1472 bytes + 8 UDP = 1480: one fragment");
        assertTrue(rule.reading(5).warnings().isEmpty(), rule.reading(5).describe());
        now[0] += 1_000_000;
        rule.accept(digest(5, 1473));
        assertEquals(2, rule.reading(5).fragments());
        assertEquals(List.of("2 IP fragments (at most 1)"), rule.reading(5).warnings());
        assertEquals(45, MatchDebugRule.fragments(65507), "the league's 64 kB");

        rule.use(new MatchDebugRule.Limits(1_000_000, 700, 0));
        assertEquals(List.of("too big: 1473 B (at most 700 B)"), rule.reading(5).warnings());
    }

    @Test
    void aProfileWithoutADebugLimitFlagsNobodyAndPartsOfADigestAreNotDatagrams() throws Exception {
        MatchDebugRule lab = rule("lab");
        run(lab, 12, 200, "PLAYING", "PLAYING");
        assertTrue(lab.broken().isEmpty());

        MatchDebugRule rule = rule("hsl-2026");
        Envelope d = digest(6, 200);
        rule.accept(d);
        rule.accept(new Envelope(d.timeMicros(), d.direction(), d.channel(), d.peer(), 6, "status", d.message(),
                new byte[50], null, d.origin(), d.authenticity(), true));
        assertTrue(rule.reading(6).warnings().isEmpty(), rule.reading(6).describe());
        assertEquals(200, rule.reading(6).biggestBytes());
    }
}
