package touchline.app.game;

import touchline.game.ManualClock;

import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.HslGameState19;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.TeamInfo;

import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Pinning and the checks on the pinned GameController, with datagrams of every format Touchline
 * decodes on the field (HL v12, HSL v20, HSL v19): each starts from the official GameController's
 * PLAYING datagram (golden file), is changed field by field, encoded by that format and decoded
 * by {@link KnownGameStateFormats} as the port watch does.
 */
class GameControllerSourcesTest {

    private static final String GC = "10.0.0.2";
    private static final String FORGER = "10.0.0.66";

    private static final List<String> FORMATS = List.of("hl12", "hsl20", "hsl19");

    private final ManualClock clock = new ManualClock(1000);
    private final KnownGameStateFormats known = new KnownGameStateFormats();

    private interface FormatCheck {
        void run(String format) throws Exception;
    }

    private static void inEveryFormat(FormatCheck check) throws Exception {
        for (String format : FORMATS) {
            check.run(format);
        }
    }

    /** Builds datagrams of one format from its golden PLAYING packet. */
    private final class Datagrams {
        final GameStateFormat format;
        final GameControlData playing;

        Datagrams(String format) throws Exception {
            this.format = switch (format) {
                case "hl12" -> new HlGameState12();
                case "hsl19" -> new HslGameState19();
                default -> new HslGameState20();
            };
            String file = format.equals("hl12") ? "04-playing.bin" : "07-playing-after-delay.bin";
            try (InputStream in = getClass().getResourceAsStream("/golden/gamecontroller/" + format + "/" + file)) {
                playing = this.format.decode(in.readAllBytes()).value();
            }
        }

        /** The datagram with these fields, as the port watch would decode it. */
        GameControlData packet(int number, int state, int scoreFirstTeam, int secsRemaining) {
            GameControlData d = playing;
            List<TeamInfo> teams = new ArrayList<>(d.teams());
            TeamInfo a = teams.get(0);
            teams.set(0, new TeamInfo(a.teamNumber(), a.colour(), a.goalkeeperColour(), scoreFirstTeam, a.penaltyShot(),
                    a.singleShots(), a.coachSequence(), a.messageBudget(), a.coach(), a.players()));
            GameControlData changed = new GameControlData(number, d.playersPerTeam(), d.gameType(), d.competitionType(),
                    state, d.firstHalf(), d.kickOffTeam(), d.secondaryState(), d.setPlayTeam(), d.setPlayMode(),
                    d.dropInTeam(), d.dropInTime(), secsRemaining, d.secondaryTime(), teams, d.gamePhase(), d.stopped());
            KnownGameStateFormats.Match m = known.decode(format.encode(changed));
            assertEquals(format.kind(), m.format().kind());
            return m.data();
        }
    }

    @Test
    void theFirstSourceIsPinnedAndAnotherIsAnIntruderShownInWords() throws Exception {
        inEveryFormat(this::theFirstSourceIsPinnedAndAnotherIsAnIntruderShownInWords);
    }

    private void theFirstSourceIsPinnedAndAnotherIsAnIntruderShownInWords(String format) throws Exception {
        Datagrams d = new Datagrams(format);
        GameControllerSources sources = new GameControllerSources(clock, null);
        assertEquals(GameControllerSources.Verdict.PINNED, sources.heard(GC, 3838, d.packet(10, 3, 1, 300)));
        assertEquals(GameControllerSources.Verdict.INTRUDER, sources.heard(FORGER, 40000, d.packet(0, 4, 1, 300)));
        assertEquals(GameControllerSources.Verdict.INTRUDER, sources.heard(FORGER, 40000, d.packet(1, 4, 1, 300)));
        assertEquals(GameControllerSources.Verdict.PINNED, sources.heard(GC, 41234, d.packet(11, 3, 1, 299)),
                "pinned by address: another port of the same host is the same GameController");
        assertEquals(GC, sources.pinnedHost());
        String warning = sources.warning();
        assertTrue(warning.contains("another source is sending game states: 10.0.0.66:40000 (2 packets, last FINISHED)"),
                warning);
        assertTrue(warning.contains("the GameController is 10.0.0.2 (first heard)"), warning);
        clock.advance(GameControllerSources.ACTIVE_MS + 1);
        assertEquals("", sources.warning(), "an intruder not heard for a while is no longer shown");
        assertEquals(1, sources.allIntruders().size());
        assertEquals(0, sources.suspicious());
    }

    /** One host sending from 10 000 ports (or 10 000 made-up addresses) costs a table of the last 64, not 10 000. */
    @Test
    void aFloodOfSourcesKeepsTheLastOnesAndCountsTheForgotten() throws Exception {
        Datagrams d = new Datagrams("hsl20");
        GameControllerSources sources = new GameControllerSources(clock, null);
        sources.heard(GC, 3838, d.packet(1, 3, 0, 600));
        GameControlData finished = d.packet(0, 4, 0, 600);
        for (int port = 1; port <= 10_000; port++) {
            sources.heard(FORGER, port, finished);
            clock.advance(1);
        }
        assertEquals(RecentSources.CAPACITY, sources.allIntruders().size());
        assertEquals(10_000 - RecentSources.CAPACITY, sources.forgottenIntruders());
        assertTrue(sources.allIntruders().stream().anyMatch(i -> i.source().equals(FORGER + ":10000")),
                "the one heard last is kept");
        assertEquals(GC, sources.pinnedHost());
        assertTrue(sources.describe().contains((10_000 - RecentSources.CAPACITY) + " other sources forgotten"),
                sources.describe());
        assertTrue(sources.warning().contains("another source is sending game states"), sources.warning());
    }

    @Test
    void aGivenAddressIsPinnedEvenWhenAnotherSpeaksFirst() throws Exception {
        Datagrams d = new Datagrams("hsl20");
        GameControllerSources sources = new GameControllerSources(clock, GC);
        assertEquals(GameControllerSources.Verdict.INTRUDER, sources.heard(FORGER, 3838, d.packet(1, 3, 0, 600)));
        assertEquals(GameControllerSources.Verdict.PINNED, sources.heard(GC, 3838, d.packet(5, 3, 0, 600)));
        assertTrue(sources.warning().contains("(given)"), sources.warning());
    }

    @Test
    void packetNumbersCountGapsAndRepeatsAndFlagGoingBack() throws Exception {
        inEveryFormat(this::packetNumbersCountGapsAndRepeatsAndFlagGoingBack);
    }

    private void packetNumbersCountGapsAndRepeatsAndFlagGoingBack(String format) throws Exception {
        Datagrams d = new Datagrams(format);
        GameControllerSources sources = new GameControllerSources(clock, null);
        sources.heard(GC, 3838, d.packet(254, 3, 0, 300));
        sources.heard(GC, 3838, d.packet(255, 3, 0, 300));
        sources.heard(GC, 3838, d.packet(2, 3, 0, 299)); // wraps; 0 and 1 lost
        sources.heard(GC, 3838, d.packet(2, 3, 0, 299));
        assertEquals(2, sources.lost());
        assertEquals(1, sources.repeats());
        assertEquals(0, sources.suspicious());
        sources.heard(GC, 3838, d.packet(200, 3, 0, 299));
        assertEquals(1, sources.suspicious());
        assertTrue(sources.warning().contains("packet number went back from 2 to 200"), sources.warning());
    }

    @Test
    void aRestartedGameControllerIsNotSuspiciousAndSilenceStartsAfresh() throws Exception {
        Datagrams d = new Datagrams("hl12");
        GameControllerSources sources = new GameControllerSources(clock, null);
        sources.heard(GC, 3838, d.packet(100, 4, 2, 0));
        sources.heard(GC, 3838, d.packet(0, 0, 0, 600));
        assertEquals(1, sources.restarts());
        assertEquals(0, sources.suspicious());
        clock.advance(GameControllerSources.SILENCE_MS + 1);
        sources.heard(GC, 3838, d.packet(77, 3, 0, 600));
        assertEquals(0, sources.suspicious(), "after a silence any packet number starts a new sequence");
        assertTrue(sources.describe().contains("1 restarts"), sources.describe());
    }

    @Test
    void impossibleJumpsAreFlagged() throws Exception {
        inEveryFormat(this::impossibleJumpsAreFlagged);
    }

    private void impossibleJumpsAreFlagged(String format) throws Exception {
        Datagrams d = new Datagrams(format);
        GameControllerSources sources = new GameControllerSources(clock, null);
        sources.heard(GC, 3838, d.packet(1, 3, 1, 300));
        sources.heard(GC, 3838, d.packet(2, 3, 2, 300)); // a goal: fine
        sources.heard(GC, 3838, d.packet(3, 3, 1, 300)); // a goal taken back: fine
        assertEquals(0, sources.suspicious());
        sources.heard(GC, 3838, d.packet(4, 3, 5, 300));
        assertTrue(sources.warning().contains("score jumped from 1 to 5"), sources.warning());
        sources.heard(GC, 3838, d.packet(5, 0, 5, 300));
        assertTrue(sources.warning().contains("state went back: PLAYING → INITIAL"), sources.warning());
        sources.heard(GC, 3838, d.packet(6, 3, 5, 300));
        assertTrue(sources.warning().contains("state skipped READY and SET: INITIAL → PLAYING"), sources.warning());
        sources.heard(GC, 3838, d.packet(7, 4, 5, 300));
        assertTrue(sources.warning().contains("FINISHED with 300 s still on the clock"), sources.warning());
        assertEquals(4, sources.suspicious());
        assertEquals(4, sources.flags().size());
    }

    @Test
    void theEndOfAHalfIsNotSuspicious() throws Exception {
        Datagrams d = new Datagrams("hsl20");
        GameControllerSources sources = new GameControllerSources(clock, null);
        sources.heard(GC, 3838, d.packet(1, 3, 1, 1));
        sources.heard(GC, 3838, d.packet(2, 4, 1, 0));
        sources.heard(GC, 3838, d.packet(3, 0, 1, 600)); // the second half's INITIAL
        sources.heard(GC, 3838, d.packet(4, 1, 1, 600));
        assertEquals(0, sources.suspicious());
        assertFalse(sources.warning().contains("SUSPICIOUS"));
    }
}
