package touchline.protocol;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import java.nio.charset.StandardCharsets;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.*;

class FrameCodecTest {

    private final FrameCodec codec = new FrameCodec();
    private final MessageCodec messages = new MessageCodec(new MessageKinds());

    /**
     * The thesis' worked keep-alive (fumanoid-protocol.md): legacy header, then robotID 1 and a
     * Status with teamID 1 and activeRole "AgentTest". The thesis prints the Status length as
     * 0x0E, which contradicts its own totals (18 protobuf bytes, 30-byte datagram); 0x0D is the
     * length those totals and the encoder agree on.
     */
    static final String WORKED_STATUS = "002a0000000000000000001208 01 ba010d 1001 7a09"
            .replace(" ", "") + HexFormat.of().formatHex("AgentTest".getBytes(StandardCharsets.US_ASCII));

    @Test
    void workedStatusExampleDecodes() {
        byte[] datagram = HexFormat.of().parseHex(WORKED_STATUS);
        assertEquals(30, datagram.length);
        var frame = assertInstanceOf(FrameResult.Frame.class, codec.decode(datagram));
        assertEquals(Framing.LEGACY, frame.framing());
        assertEquals(18, frame.payload().length);
        var decoded = assertInstanceOf(MessageResult.Decoded.class, messages.decode(frame.payload()));
        assertEquals(1, decoded.message().getRobotID());
        assertEquals(23, decoded.extension());
        assertEquals("status", decoded.kind());
        Fumanoid.Status status = decoded.message().getExtension(Fumanoid.status);
        assertEquals(1, status.getTeamID());
        assertEquals("AgentTest", status.getActiveRole());
    }

    @Test
    void workedStatusExampleEncodesByteForByte() {
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(1)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(1).setActiveRole("AgentTest").build())
                .build();
        assertEquals(WORKED_STATUS, HexFormat.of().formatHex(codec.encode(Framing.LEGACY, m.toByteArray())));
    }

    @Test
    void lengthPrefixFramingGolden() {
        byte[] payload = {0x08, 0x07};
        byte[] datagram = codec.encode(Framing.LENGTH_PREFIX, payload);
        assertEquals("000000020807", HexFormat.of().formatHex(datagram));
        var frame = assertInstanceOf(FrameResult.Frame.class, codec.decode(datagram));
        assertEquals(Framing.LENGTH_PREFIX, frame.framing());
        assertArrayEquals(payload, frame.payload());
    }

    @Test
    void truncatedLegacyHeaderIsMalformed() {
        var m = assertInstanceOf(FrameResult.Malformed.class, codec.decode(HexFormat.of().parseHex("002a000000")));
        assertTrue(m.reason().contains("truncated legacy header"), m.reason());
    }

    @Test
    void truncatedLengthHeaderIsMalformed() {
        var m = assertInstanceOf(FrameResult.Malformed.class, codec.decode(new byte[]{0, 0}));
        assertTrue(m.reason().contains("truncated"), m.reason());
    }

    @Test
    void lengthDisagreeingWithDatagramIsMalformed() {
        byte[] d = HexFormat.of().parseHex("002a00000000000000000063" + "0801");
        var m = assertInstanceOf(FrameResult.Malformed.class, codec.decode(d));
        assertEquals("legacy header says 99 payload bytes, datagram has 2", m.reason());
        var m2 = assertInstanceOf(FrameResult.Malformed.class, codec.decode(HexFormat.of().parseHex("000000090801")));
        assertEquals("length header says 9 payload bytes, datagram has 2", m2.reason());
    }

    @Test
    void datagramOverLimitIsMalformed() {
        byte[] d = codec.encode(Framing.LENGTH_PREFIX, new byte[1396]);
        assertInstanceOf(FrameResult.Frame.class, codec.decode(d));
        byte[] big = new byte[1401];
        var m = assertInstanceOf(FrameResult.Malformed.class, codec.decode(big));
        assertTrue(m.reason().contains("1400"), m.reason());
        assertThrows(IllegalArgumentException.class, () -> codec.encode(Framing.LEGACY, new byte[1389]));
    }

    @Test
    void datagramClassesByFirstBytes() {
        assertEquals(DatagramClass.GAMECONTROLLER, DatagramClass.of("RGme".getBytes(StandardCharsets.US_ASCII), 4));
        assertEquals(DatagramClass.FUMANOID, DatagramClass.of(HexFormat.of().parseHex(WORKED_STATUS), 30));
        assertEquals(DatagramClass.FUMANOID, DatagramClass.of(HexFormat.of().parseHex("000000020807"), 6));
        assertEquals(DatagramClass.RELIABLE_STREAM, DatagramClass.of(new byte[]{5, 4, 'h', 'i'}, 4));
        assertEquals(DatagramClass.RELIABLE_STREAM, DatagramClass.of(new byte[]{3, 2}, 2));
    }
}
