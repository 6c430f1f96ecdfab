package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.nio.ByteBuffer;
import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SplGameState18Test {

    private final SplGameState18 format = new SplGameState18();

    private static GameControlData splGame(int kickOff, int secondary, int setPlayTeam) {
        TeamInfo a = new TeamInfo(13, 1, 6, 3, 2, 0x0105, 0, 1200, RobotInfo.EMPTY,
                Fixtures.players(20, new RobotInfo(2, 17, 0, 0, 0, false), new RobotInfo(14, 0, 0, 0, 0, true)));
        TeamInfo b = new TeamInfo(200, 0, 5, 0, 1, 0x8001, 0, 65535, RobotInfo.EMPTY,
                Fixtures.players(20, new RobotInfo(15, 0, 0, 0, 0, true), new RobotInfo(7, 45, 0, 0, 0, false)));
        return new GameControlData(9, 7, 1, 0, 3, true, kickOff, secondary, setPlayTeam, 0, 0, 0, -3, -5,
                List.of(a, b));
    }

    private static byte[] expected(int kickingTeam, int gamePhase, int setPlay) {
        ByteBuffer b = Fixtures.expected(118);
        b.put(4, (byte) 18).put(5, (byte) 9).put(6, (byte) 7).put(7, (byte) 1).put(8, (byte) 0)
                .put(9, (byte) gamePhase).put(10, (byte) 3).put(11, (byte) setPlay).put(12, (byte) 1)
                .put(13, (byte) kickingTeam).putShort(14, (short) -3).putShort(16, (short) -5);
        int t0 = 18;
        b.put(t0, (byte) 13).put(t0 + 1, (byte) 1).put(t0 + 2, (byte) 6).put(t0 + 3, (byte) 20).put(t0 + 4, (byte) 3)
                .put(t0 + 5, (byte) 2).putShort(t0 + 6, (short) 0x0105).putShort(t0 + 8, (short) 1200);
        b.put(t0 + 10, (byte) 2).put(t0 + 11, (byte) 17).put(t0 + 10 + 38, (byte) 14);
        int t1 = 68;
        b.put(t1, (byte) 200).put(t1 + 1, (byte) 0).put(t1 + 2, (byte) 5).put(t1 + 3, (byte) 1).put(t1 + 5, (byte) 1)
                .putShort(t1 + 6, (short) 0x8001).putShort(t1 + 8, (short) 65535);
        b.put(t1 + 10, (byte) 15).put(t1 + 48, (byte) 7).put(t1 + 49, (byte) 45);
        return b.array();
    }

    @Test
    void encodesEveryFieldAtItsOffset() {
        assertEquals(HexFormat.of().formatHex(expected(13, 0, 0)),
                HexFormat.of().formatHex(format.encode(splGame(13, 0, 0))));
    }

    @Test
    void dropBallIsKickingTeamNone255() {
        assertEquals(HexFormat.of().formatHex(expected(255, 0, 0)),
                HexFormat.of().formatHex(format.encode(splGame(GameControlData.DROP_BALL, 0, 0))));
    }

    @Test
    void setPlaysAndPhasesAreSplitIntoGamePhaseAndSetPlay() {
        // corner kick for team 200 -> setPlay 3, kicking team 200
        assertEquals(HexFormat.of().formatHex(expected(200, 0, 3)),
                HexFormat.of().formatHex(format.encode(splGame(13, 7, 200))));
        // timeout -> gamePhase 3
        assertEquals(HexFormat.of().formatHex(expected(13, 3, 0)),
                HexFormat.of().formatHex(format.encode(splGame(13, 3, 0))));
    }

    @Test
    void hlPenaltiesAreTranslated() {
        assertEquals(2, SplGameState18.splPenalty(31));
        assertEquals(1, SplGameState18.splPenalty(30));
        assertEquals(7, SplGameState18.splPenalty(34));
        assertEquals(15, SplGameState18.splPenalty(15));
    }

    @Test
    void roundTrips() {
        for (GameControlData d : List.of(splGame(13, 0, 0), splGame(GameControlData.DROP_BALL, 1, 0),
                splGame(200, 7, 200))) {
            Decoded<GameControlData> back = format.decode(format.encode(d));
            assertTrue(back.isOk(), back.toString());
            assertEquals(d, back.value());
        }
    }

    @Test
    void rejectsWrongLengthMagicAndVersion() {
        byte[] good = expected(13, 0, 0);
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(java.util.Arrays.copyOf(good, 117)).failure());
        byte[] magic = good.clone();
        magic[0] = 'X';
        assertEquals(DecodeFailure.WRONG_MAGIC, format.decode(magic).failure());
        byte[] version = good.clone();
        version[4] = 17;
        assertEquals(DecodeFailure.WRONG_VERSION, format.decode(version).failure());
    }
}
