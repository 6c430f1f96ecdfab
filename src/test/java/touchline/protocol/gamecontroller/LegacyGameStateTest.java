package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** v8 (2014, 158 B) and v7 (2013 / HL compatibility, 116 B). */
class LegacyGameStateTest {

    private final GameState8 v8 = new GameState8();
    private final GameState7 v7 = new GameState7();

    private static byte[] expected8(int kickOffColour, int secondary) {
        ByteBuffer b = Fixtures.expected(158);
        b.put(4, (byte) 8).put(5, (byte) 255).put(6, (byte) 4).put(7, (byte) 3).put(8, (byte) 0)
                .put(9, (byte) kickOffColour).put(10, (byte) secondary).put(11, (byte) 0)
                .putShort(12, (short) 0xFFFF).putShort(14, (short) -3).putShort(16, (short) -5);
        int t0 = 18;
        b.put(t0, (byte) 13).put(t0 + 1, (byte) 1).put(t0 + 2, (byte) 3).put(t0 + 3, (byte) 2)
                .putShort(t0 + 4, (short) 0x0105);
        b.put(t0 + 48, (byte) 2).put(t0 + 49, (byte) 17);            // player 1: HL physical contact = 2 in 2014
        b.put(t0 + 48 + 20, (byte) 14);                               // player 11: substitute
        int t1 = 88;
        b.put(t1, (byte) 200).put(t1 + 1, (byte) 0).put(t1 + 3, (byte) 1).putShort(t1 + 4, (short) 0x8001);
        b.put(t1 + 48, (byte) 15);                                    // manual
        b.put(t1 + 68, (byte) 5).put(t1 + 69, (byte) 250);            // pickup/incapable = 5 in 2014
        return b.array();
    }

    @Test
    void v8EncodesEveryFieldWithKickOffAsColour() {
        GameControlData d = Fixtures.game(11, 200, 2, 0, 0, false);
        assertEquals(HexFormat.of().formatHex(expected8(0, 2)), HexFormat.of().formatHex(v8.encode(d)));
        GameControlData red = Fixtures.game(11, 13, 0, 0, 0, false);
        assertEquals(HexFormat.of().formatHex(expected8(1, 0)), HexFormat.of().formatHex(v8.encode(red)));
    }

    @Test
    void v8DropBallIsColour2AndSetPlaysAreSentAsNormal() {
        GameControlData d = Fixtures.game(11, GameControlData.DROP_BALL, 7, 13, 1, false);
        assertEquals(HexFormat.of().formatHex(expected8(2, 0)), HexFormat.of().formatHex(v8.encode(d)));
    }

    @Test
    void v8RoundTripsAndRejectsBadInput() {
        GameControlData d = Fixtures.game(11, 200, 1, 0, 0, false);
        Decoded<GameControlData> back = v8.decode(v8.encode(d));
        assertTrue(back.isOk(), back.toString());
        assertEquals(d, back.value());
        assertEquals(GameControlData.DROP_BALL, v8.decode(expected8(2, 0)).value().kickOffTeam());
        assertEquals(DecodeFailure.WRONG_LENGTH, v8.decode(Arrays.copyOf(expected8(0, 0), 159)).failure());
        byte[] version = expected8(0, 0);
        version[4] = 9;
        assertEquals(DecodeFailure.WRONG_VERSION, v8.decode(version).failure());
        byte[] magic = expected8(0, 0);
        magic[1] = 'X';
        assertEquals(DecodeFailure.WRONG_MAGIC, v8.decode(magic).failure());
        byte[] colour = expected8(0, 0);
        colour[9] = 5;
        assertEquals(DecodeFailure.INVALID_FIELD, v8.decode(colour).failure());
    }

    private static byte[] expected7(int kickOffColour) {
        ByteBuffer b = Fixtures.expected(116);
        b.putInt(4, 7).put(8, (byte) 4).put(9, (byte) 3).put(10, (byte) 0).put(11, (byte) kickOffColour)
                .put(12, (byte) 0).put(13, (byte) 0).putShort(14, (short) 0xFFFF).putInt(16, -3);
        // blue team (200, colour 0) first, whatever its side
        int t0 = 20;
        b.put(t0, (byte) 200).put(t0 + 1, (byte) 0).put(t0 + 2, (byte) 1).put(t0 + 3, (byte) 0);
        b.putShort(t0 + 4, (short) 15);
        b.putShort(t0 + 4 + 40, (short) 5).putShort(t0 + 4 + 42, (short) 250);
        int t1 = 68;
        b.put(t1, (byte) 13).put(t1 + 1, (byte) 1).put(t1 + 2, (byte) 1).put(t1 + 3, (byte) 3);
        b.putShort(t1 + 4, (short) 2).putShort(t1 + 6, (short) 17);
        b.putShort(t1 + 4 + 40, (short) 14);
        return b.array();
    }

    @Test
    void v7OrdersTeamsByColourAndUsesU32Fields() {
        GameControlData d = Fixtures.game(11, 13, 0, 0, 0, false);
        assertEquals(HexFormat.of().formatHex(expected7(1)), HexFormat.of().formatHex(v7.encode(d)));
        GameControlData drop = Fixtures.game(11, GameControlData.DROP_BALL, 3, 0, 0, false);
        assertEquals(HexFormat.of().formatHex(expected7(2)), HexFormat.of().formatHex(v7.encode(drop)));
    }

    @Test
    void v7DecodesAndRejectsBadInput() {
        Decoded<GameControlData> back = v7.decode(expected7(1));
        assertTrue(back.isOk(), back.toString());
        assertEquals(13, back.value().kickOffTeam());
        assertEquals(-3, back.value().secsRemaining());
        assertEquals(200, back.value().teams().get(0).teamNumber());
        assertEquals(31, back.value().team(13).player(1).penalty());
        assertEquals(DecodeFailure.WRONG_LENGTH, v7.decode(Arrays.copyOf(expected7(1), 158)).failure());
        byte[] version = expected7(1);
        version[4] = 8;
        assertEquals(DecodeFailure.WRONG_VERSION, v7.decode(version).failure());
        byte[] highVersion = expected7(1);
        highVersion[7] = 1; // u32: 0x01000007 is not 7
        assertEquals(DecodeFailure.WRONG_VERSION, v7.decode(highVersion).failure());
    }
}
