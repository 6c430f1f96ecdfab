package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ReturnPacketTest {

    private final ReturnPacketDecoder decoder = new ReturnPacketDecoder();

    @Test
    void v2IsTeamThenPlayer() {
        byte[] bytes = new ReturnPacket.V2(200, 11, ReturnPacket.MAN_UNPENALISE).encode();
        assertEquals("5247727402c80b01", HexFormat.of().formatHex(bytes));
        assertEquals(new ReturnPacket.V2(200, 11, 1), decoder.decode(bytes).value());
    }

    @Test
    void v1HasU32VersionAndU16TeamAndPlayer() {
        byte[] bytes = new ReturnPacket.V1(13, 1, ReturnPacket.ALIVE).encode();
        assertEquals("52477274" + "01000000" + "0d00" + "0100" + "02000000", HexFormat.of().formatHex(bytes));
        assertEquals(new ReturnPacket.V1(13, 1, 2), decoder.decode(bytes).value());
    }

    private static byte[] v4Bytes(int player, int team, int fallen, float x) {
        ByteBuffer b = ByteBuffer.allocate(32).order(ByteOrder.LITTLE_ENDIAN);
        b.put(new byte[]{'R', 'G', 'r', 't', 4, (byte) player, (byte) team, (byte) fallen});
        b.putFloat(x).putFloat(-1500f).putFloat(1.5f).putFloat(-1f).putFloat(250f).putFloat(-30f);
        return b.array();
    }

    @Test
    void v4IsPlayerThenTeamWithPoseAndBall() {
        ReturnPacket.V4 p = new ReturnPacket.V4(20, 7, 1, 3000f, -1500f, 1.5f, -1f, 250f, -30f);
        assertEquals(HexFormat.of().formatHex(v4Bytes(20, 7, 1, 3000f)), HexFormat.of().formatHex(p.encode()));
        Decoded<ReturnPacket> back = decoder.decode(p.encode());
        assertTrue(back.isOk(), back.toString());
        assertEquals(p, back.value());
        assertEquals(7, back.value().team());
        assertEquals(20, back.value().player());
    }

    @Test
    void rejectsWrongSizeUnknownVersionAndBadFields() {
        byte[] v2 = new ReturnPacket.V2(13, 2, 2).encode();
        assertEquals(DecodeFailure.WRONG_LENGTH, decoder.decode(Arrays.copyOf(v2, 9)).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, decoder.decode(new byte[3]).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, decoder.decode(null).failure());
        byte[] v3 = v2.clone();
        v3[4] = 3;
        assertEquals(DecodeFailure.WRONG_VERSION, decoder.decode(v3).failure());
        byte[] magic = v2.clone();
        magic[2] = 'm';
        assertEquals(DecodeFailure.WRONG_MAGIC, decoder.decode(magic).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(new ReturnPacket.V2(13, 0, 2).encode()).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(new ReturnPacket.V2(13, 200, 2).encode()).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(new ReturnPacket.V2(13, 2, 9).encode()).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(v4Bytes(200, 7, 0, 1f)).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(v4Bytes(0, 7, 0, 1f)).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(v4Bytes(3, 7, 0, Float.NaN)).failure());
        assertEquals(DecodeFailure.INVALID_FIELD, decoder.decode(v4Bytes(3, 7, 255, 1f)).failure());
        assertEquals(DecodeFailure.WRONG_LENGTH, decoder.decode(Arrays.copyOf(v4Bytes(3, 7, 0, 1f), 36)).failure());
        assertTrue(decoder.decode(v4Bytes(3, 7, 0, 1f)).isOk());
    }
}
