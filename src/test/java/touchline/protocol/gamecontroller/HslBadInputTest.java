package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Bad HSL game-state datagrams on the network: each is rejected with the reason of the format
 * its header and version claim, and the next good datagram is recognised as usual.
 */
class HslBadInputTest {

    private final HslGolden golden = new HslGolden("hsl20");
    private final KnownGameStateFormats known = new KnownGameStateFormats();
    private final byte[] playing = golden.bytes("07-playing-after-delay.bin");

    private Decoded<KnownGameStateFormats.Match> thenGood(byte[] bad) {
        Decoded<KnownGameStateFormats.Match> verdict = known.recognise(bad);
        Decoded<KnownGameStateFormats.Match> next = known.recognise(playing);
        assertTrue(next.isOk(), "the next good datagram is used: " + next);
        assertEquals(GameControlData.STATE_PLAYING, next.value().data().state());
        return verdict;
    }

    private static byte[] with(byte[] bytes, int offset, int value) {
        byte[] out = bytes.clone();
        out[offset] = (byte) value;
        return out;
    }

    @Test
    void wrongLengthIsNamedByTheVersionByte() {
        Decoded<KnownGameStateFormats.Match> d = thenGood(Arrays.copyOf(playing, 157));
        assertEquals(DecodeFailure.WRONG_LENGTH, d.failure());
        assertTrue(d.detail().startsWith("gc.hsl20 (version 20, 158 bytes): expected 158 bytes, got 157"), d.detail());
        assertEquals(DecodeFailure.WRONG_LENGTH, thenGood(Arrays.copyOf(playing, 198)).failure());
    }

    @Test
    void splVersion18BytesLabelledAsVersion20() {
        byte[] spl = new SplGameState18().encode(new HslGameState20().decode(playing).value());
        assertEquals(118, spl.length);
        assertTrue(known.recognise(spl).isOk(), "as SPL v18 they are fine");
        Decoded<KnownGameStateFormats.Match> d = thenGood(with(spl, 4, 20));
        assertEquals(DecodeFailure.WRONG_LENGTH, d.failure());
        assertTrue(d.detail().contains("gc.hsl20") && d.detail().contains("got 118"), d.detail());
    }

    @Test
    void unknownVersionOfTheRightSize() {
        Decoded<KnownGameStateFormats.Match> d = thenGood(with(playing, 4, 21));
        assertEquals(DecodeFailure.WRONG_VERSION, d.failure());
        assertTrue(d.detail().contains("version byte 21"), d.detail());
        // 158 bytes with version 8 is the 2014 format, not a broken v20
        assertTrue(known.recognise(new GameState8().encode(new HslGameState20().decode(playing).value())).isOk());
    }

    @Test
    void valuesOutOfRange() {
        int player1OfTeam0 = 18 + 10;
        int[][] cases = {{7, 3}, {8, 2}, {9, 4}, {10, 5}, {11, 7}, {12, 2}, {6, 21}, {19, 10}, {20, 10}, {21, 21},
                {player1OfTeam0, 14}, {18 + 70 + 10 + 3 * 19, 200}};
        String[] reasons = {"competitionType 3", "stopped 2", "gamePhase 4", "state 5", "setPlay 7", "firstHalf 2",
                "playersPerTeam 21", "colour 10", "colour 1/10", "goalkeeper 21", "player 1: penalty 14",
                "teams[1] player 20: penalty 200"};
        for (int i = 0; i < cases.length; i++) {
            Decoded<KnownGameStateFormats.Match> d = thenGood(with(playing, cases[i][0], cases[i][1]));
            assertEquals(DecodeFailure.INVALID_FIELD, d.failure(), reasons[i]);
            assertTrue(d.detail().contains(reasons[i]), d.detail());
        }
        // v19 numbers penalties only up to 11 (SUBSTITUTE): its 12 is out of range, v20's 12 is SENT_OFF
        byte[] v19 = golden19("00-initial.bin");
        assertEquals(DecodeFailure.INVALID_FIELD, known.recognise(with(v19, 18 + 10, 12)).failure());
        assertTrue(known.recognise(with(playing, player1OfTeam0, 12)).isOk());
    }

    private static byte[] golden19(String file) {
        return new HslGolden("hsl19").bytes(file);
    }

    @Test
    void trueDataWithTheWrongLayout() {
        byte[] monitor = golden.bytes("05-playing-delayed.monitor.bin");
        Decoded<KnownGameStateFormats.Match> d = thenGood(Arrays.copyOf(monitor, 118));
        assertEquals(DecodeFailure.WRONG_LENGTH, d.failure());
        assertTrue(d.detail().startsWith("gc.hsl20.truedata"), d.detail());
        assertEquals(DecodeFailure.WRONG_MAGIC, known.recognise(new byte[]{'R', 'G', 'r', 't', 4}).failure());
    }
}
