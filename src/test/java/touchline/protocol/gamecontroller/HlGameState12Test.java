package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.nio.ByteBuffer;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

class HlGameState12Test {

    private final HlGameState12 format = new HlGameState12();

    /** Bytes written field by field from the brief's table (1.2), not by the serializer. */
    private static byte[] expected(int kickOffByte) {
        ByteBuffer b = Fixtures.expected(688);
        b.putShort(4, (short) 12);
        b.put(6, (byte) 255).put(7, (byte) 4).put(8, (byte) 1).put(9, (byte) 3).put(10, (byte) 0);
        b.put(11, (byte) kickOffByte).put(12, (byte) 7).put(13, (byte) 13).put(14, (byte) 1);
        b.put(17, (byte) 0).putShort(18, (short) 0xFFFF);
        b.putShort(20, (short) -3).putShort(22, (short) -5);
        int t0 = 24;
        b.put(t0, (byte) 13).put(t0 + 1, (byte) 1).put(t0 + 2, (byte) 3).put(t0 + 3, (byte) 2)
                .putShort(t0 + 4, (short) 0x0105);
        int p1 = t0 + 266;
        b.put(p1, (byte) 31).put(p1 + 1, (byte) 17).put(p1 + 2, (byte) 1).put(p1 + 3, (byte) 2).put(p1 + 4, (byte) 3)
                .put(p1 + 5, (byte) 1);
        int p11 = t0 + 266 + 6 * 10;
        b.put(p11, (byte) 14).put(p11 + 2, (byte) 4).put(p11 + 3, (byte) 5).put(p11 + 4, (byte) 6);
        int t1 = 24 + 332;
        b.put(t1, (byte) 200).put(t1 + 1, (byte) 0).put(t1 + 3, (byte) 1).putShort(t1 + 4, (short) 0x8001);
        int q1 = t1 + 266;
        b.put(q1, (byte) 15).put(q1 + 3, (byte) 1);
        int q11 = t1 + 266 + 60;
        b.put(q11, (byte) 34).put(q11 + 1, (byte) 250).put(q11 + 4, (byte) 1).put(q11 + 5, (byte) 1);
        return b.array();
    }

    @Test
    void encodesEveryFieldAtItsOffset() {
        GameControlData d = Fixtures.game(11, 7, 7, 13, 1, true);
        assertEquals(HexFormat.of().formatHex(expected(7)), HexFormat.of().formatHex(format.encode(d)));
    }

    @Test
    void dropBallIs0x80LikeTheJavaGameControllerOr255WhenConfigured() {
        GameControlData d = Fixtures.game(11, GameControlData.DROP_BALL, 7, 13, 1, true);
        assertArrayEquals(expected(0x80), format.encode(d));
        assertArrayEquals(expected(255), new HlGameState12(255).encode(d));
        assertEquals(GameControlData.DROP_BALL, format.decode(expected(255)).value().kickOffTeam());
    }

    @Test
    void roundTrips() {
        GameControlData d = Fixtures.game(11, 200, 4, 200, 2, true);
        Decoded<GameControlData> back = format.decode(format.encode(d));
        assertTrue(back.isOk(), back.toString());
        assertEquals(d, back.value());
        assertEquals(-3, back.value().secsRemaining());
    }

    @Test
    void rejectsWrongLengthMagicAndVersion() {
        byte[] good = expected(7);
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(java.util.Arrays.copyOf(good, 640)).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(new byte[0]).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(null).failure());
        byte[] magic = good.clone();
        magic[3] = 'x';
        assertEquals(DecodeFailure.WRONG_MAGIC, format.decode(magic).failure());
        byte[] version = good.clone();
        version[4] = 18;
        Decoded<GameControlData> bad = format.decode(version);
        assertFalse(bad.isOk());
        assertEquals(DecodeFailure.WRONG_VERSION, bad.failure());
        // a 158-byte v8 packet is not accepted as HL v12 either
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(new GameState8().encode(
                Fixtures.game(11, 13, 0, 0, 0, false))).failure());
    }

    @Test
    void legacy640LayoutHasFourByteRobotInfo() {
        HlGameState12 legacy = HlGameState12.legacy640();
        GameControlData d = Fixtures.game(11, 7, 0, 0, 0, true);
        byte[] bytes = legacy.encode(d);
        assertEquals(640, bytes.length);
        assertEquals(640, legacy.size());
        assertEquals("gc.hl12-640", legacy.kind());
        ByteBuffer b = ByteBuffer.wrap(bytes).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        assertEquals(12, b.getShort(4));
        int t0 = 24;
        assertEquals(13, b.get(t0));
        int p1 = t0 + 264; // coach at 260 (4 bytes), players at 264
        assertEquals(31, b.get(p1));
        assertEquals(17, b.get(p1 + 1));
        assertEquals(2, b.get(p1 + 2), "yellow cards follow secsTillUnpenalised directly");
        assertEquals(3, b.get(p1 + 3));
        int t1 = 24 + 308;
        assertEquals((byte) 200, b.get(t1));
        int q11 = t1 + 264 + 4 * 10;
        assertEquals(34, b.get(q11));
        assertEquals((byte) 250, b.get(q11 + 1));
        assertEquals(1, b.get(q11 + 3));
        Decoded<GameControlData> back = legacy.decode(bytes);
        assertTrue(back.isOk(), back.toString());
        assertEquals(2, back.value().team(13).player(1).yellowCards());
        assertEquals(0, back.value().team(13).player(1).warnings(), "no warnings in the 640-byte layout");
        assertEquals(DecodeFailure.WRONG_LENGTH, legacy.decode(expected(7)).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, format.decode(bytes).failure());
    }
}
