package touchline.game;

import org.junit.jupiter.api.Test;
import touchline.protocol.gamecontroller.HlGameState12;

import java.io.IOException;
import java.io.InputStream;
import java.util.HexFormat;
import java.util.List;
import java.util.function.Consumer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Replays the script of the golden capture (official HL GameController v2024.1, see
 * golden/gamecontroller/hl12/README.md) through our game logic and HL v12 serializer and
 * compares every datagram byte for byte, packetNumber (byte 6) aside.
 */
class GoldenReplayTest {

    private record Step(String file, long clockMs, Consumer<Game> commands) {
    }

    @SafeVarargs
    private static Consumer<Game> act(LeagueAction<? super GameState>... actions) {
        return g -> {
            for (LeagueAction<? super GameState> a : actions) {
                Outcome o = g.perform(a);
                assertTrue(o.applied(), o.message());
            }
        };
    }

    private static final Consumer<Game> NONE = g -> { };

    private static final List<Step> SCRIPT = List.of(
            new Step("00-initial.bin", 10000, NONE),
            new Step("01-ready.bin", 10000, act(new ToReady())),
            new Step("02-ready-after-10s.bin", 20000, NONE),
            new Step("03-set.bin", 25000, act(new ToSet())),
            new Step("04-playing.bin", 28000, act(new ToPlaying())),
            new Step("05-playing-after-20s.bin", 48000, NONE),
            new Step("06-goal-team13.bin", 53000, act(new Goal(13))),
            new Step("07-set-after-goal.bin", 61000, act(new ToSet())),
            new Step("08-playing-after-goal.bin", 63000, act(new ToPlaying())),
            new Step("09-penalty-team7-player2-physical-contact.bin", 78000,
                    act(new Penalize(7, 2, Penalty.PHYSICAL_CONTACT))),
            new Step("10-penalty-countdown-after-12s.bin", 90000, NONE),
            new Step("11-penalty-served-after-31s.bin", 109000, NONE),
            new Step("12-yellow-card-team7-player3.bin", 111000, act(new Card(7, 3, Card.Kind.YELLOW))),
            new Step("13-warning-team13-player1.bin", 113000, act(new Card(13, 1, Card.Kind.WARNING))),
            new Step("14-direct-freekick-team13.bin", 116000,
                    act(new StartSetPlay(13, SecondaryState.DIRECT_FREEKICK))),
            new Step("15-direct-freekick-team13-ready.bin", 120000, act(new SetPlayStep(SetPlayStep.Step.READY))),
            new Step("16-direct-freekick-team13-prepare.bin", 135000,
                    act(new SetPlayStep(SetPlayStep.Step.PREPARE))),
            new Step("17-direct-freekick-team13-execute.bin", 138000,
                    act(new SetPlayStep(SetPlayStep.Step.EXECUTE))),
            new Step("18-corner-kick-team7.bin", 148000, act(new StartSetPlay(7, SecondaryState.CORNER_KICK))),
            new Step("19-corner-kick-team7-ready.bin", 151000, act(new SetPlayStep(SetPlayStep.Step.READY))),
            new Step("20-corner-kick-team7-abort.bin", 156000, act(new SetPlayStep(SetPlayStep.Step.ABORT))),
            new Step("21-dropped-ball.bin", 161000, act(new DropBall())),
            new Step("22-set-after-dropped-ball.bin", 171000, act(new ToSet())),
            new Step("23-playing-after-dropped-ball.bin", 173000, act(new ToPlaying())),
            new Step("24-finished-first-half.bin", 203000, act(new ToFinished())),
            new Step("25-second-half-initial.bin", 203000, NONE),
            new Step("26-second-half-initial-after-5s.bin", 208000, NONE),
            new Step("27-second-half-ready.bin", 213000, act(new ToReady())),
            new Step("28-second-half-set.bin", 223000, act(new ToSet())),
            new Step("29-second-half-playing.bin", 225000, act(new ToPlaying())),
            new Step("30-finished.bin", 285000, act(new ToFinished())));

    @Test
    void replayReproducesEveryGoldenDatagram() throws IOException {
        ManualClock clock = new ManualClock(10000);
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, clock);
        HlGameState12 format = new HlGameState12();
        assertEquals(31, SCRIPT.size());
        for (Step step : SCRIPT) {
            clock.set(step.clockMs);
            game.advance(); // the sender's tick between steps
            step.commands.accept(game);
            byte[] expected = golden(step.file);
            byte[] actual = format.encode(game.controlData().withPacketNumber(expected[6] & 0xFF));
            assertEquals(HexFormat.of().formatHex(expected), HexFormat.of().formatHex(actual),
                    step.file + " differs at byte " + firstDifference(expected, actual));
        }
    }

    @Test
    void everyGoldenDatagramDecodesAndReencodesIdentically() throws IOException {
        HlGameState12 format = new HlGameState12();
        for (Step step : SCRIPT) {
            byte[] expected = golden(step.file);
            var decoded = format.decode(expected);
            assertTrue(decoded.isOk(), step.file + ": " + decoded);
            assertEquals(HexFormat.of().formatHex(expected), HexFormat.of().formatHex(format.encode(decoded.value())),
                    step.file);
        }
    }

    static byte[] golden(String file) throws IOException {
        try (InputStream in = GoldenReplayTest.class.getResourceAsStream("/golden/gamecontroller/hl12/" + file)) {
            assertNotNull(in, file);
            return in.readAllBytes();
        }
    }

    private static int firstDifference(byte[] a, byte[] b) {
        for (int i = 0; i < Math.min(a.length, b.length); i++) {
            if (a[i] != b[i]) {
                return i;
            }
        }
        return a.length == b.length ? -1 : Math.min(a.length, b.length);
    }
}
