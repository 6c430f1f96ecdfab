package touchline.protocol.ros2;

import org.junit.jupiter.api.Test;

import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Bad input, hand-made layouts and the edges of CDR; the real serializer's bytes are in {@link CdrDecoderInteropTest}. */
class CdrDecoderTest {

    private static CdrDecoder decoder(String root, String text) {
        DefinitionResult r = new DefinitionParser().parse(root, "ros2msg", text);
        return new CdrDecoder(assertInstanceOf(DefinitionResult.Parsed.class, r, r.toString()).definition());
    }

    private static CdrDecoder real(String type) {
        return decoder(type, Ros2Sources.definition(type));
    }

    static byte[] golden(String name) throws Exception {
        try (InputStream in = CdrDecoderTest.class.getResourceAsStream("/ros2/cdr/" + name)) {
            return in.readAllBytes();
        }
    }

    private static String refusal(DecodeResult r) {
        return assertInstanceOf(DecodeResult.Undecodable.class, r, r.toString()).reason();
    }

    private static RosMessage decoded(DecodeResult r) {
        return assertInstanceOf(DecodeResult.Decoded.class, r, r.toString()).message();
    }

    @Test
    void alignmentCountsFromAfterTheHeaderInBothByteOrders() {
        CdrDecoder d = decoder("t/msg/A", "uint8 a\nfloat64 b\nuint16 c\nint32[] d\nstring e\nint8 f\n");
        // little-endian: a at 0, pad to 8, b at 8..16, c at 16, pad to 20, count at 20, d at 24..32, e at 32
        ByteBuffer le = ByteBuffer.allocate(4 + 44).order(ByteOrder.LITTLE_ENDIAN);
        le.put(new byte[]{0, 1, 0, 0}).put((byte) 200).position(4 + 8);
        le.putDouble(-0.5).putShort((short) 65535).position(4 + 20);
        le.putInt(2).putInt(-7).putInt(9).putInt(3).put("hi\0".getBytes()).put((byte) -3);
        RosMessage m = decoded(d.decode(Arrays.copyOf(le.array(), 4 + 40)));
        ByteBuffer be = ByteBuffer.allocate(4 + 44).order(ByteOrder.BIG_ENDIAN);
        be.put(new byte[]{0, 0, 0, 0}).put((byte) 200).position(4 + 8);
        be.putDouble(-0.5).putShort((short) 65535).position(4 + 20);
        be.putInt(2).putInt(-7).putInt(9).putInt(3).put("hi\0".getBytes()).put((byte) -3);
        RosMessage n = decoded(d.decode(Arrays.copyOf(be.array(), 4 + 40)));
        for (RosMessage x : new RosMessage[]{m, n}) {
            assertEquals(200, x.get("a"));
            assertEquals(-0.5, x.get("b"));
            assertEquals(65535, x.get("c"));
            assertArrayEquals(new int[]{-7, 9}, (int[]) x.get("d"));
            assertEquals("hi", x.get("e"));
            assertEquals(-3, x.get("f"));
        }
        assertEquals("{a: 200, b: -0.5, c: 65535, d: [-7, 9], e: \"hi\", f: -3}", m.line(200));
    }

    @Test
    void unsignedValuesReadUnsigned() {
        CdrDecoder d = decoder("t/msg/U", "uint64 big\nuint32[] words\nuint8[] bytes\nint8[] signed\n");
        // big at 0, words' count at 8 and element at 12, bytes' count at 16 and data at 20, signed's count at 24
        ByteBuffer b = ByteBuffer.allocate(4 + 30).order(ByteOrder.LITTLE_ENDIAN);
        b.put(new byte[]{0, 1, 0, 0}).putLong(-1L).putInt(1).putInt(-1).putInt(2).put((byte) -1).put((byte) 1)
                .position(4 + 24).putInt(2).put((byte) -1).put((byte) 1);
        RosMessage m = decoded(d.decode(b.array()));
        assertEquals(1.8446744073709552E19, m.number("big"));
        assertEquals("{big: 18446744073709551615, words: [4294967295], bytes: <2 bytes>, signed: <2 bytes>}", m.line(200));
        assertEquals(4294967295.0, m.number("words[0]"));
        assertEquals(255.0, m.number("bytes[0]"));
        assertEquals(-1.0, m.number("signed[0]"));
        assertEquals(java.util.List.of("big", "words[0]"), m.numericPaths(), "8-bit arrays are no plot fields");
    }

    @Test
    void anEmptyTypeIsOneByteAndBoolsAndWstrings() {
        CdrDecoder d = decoder("t/msg/E", "Empty e\nbool[2] flags\nwstring w\n===\nMSG: t/Empty\n");
        byte[] bytes = {0, 1, 0, 0, /* e */ 0, /* flags */ 1, 0, /* pad */ 0, 2, 0, 0, 0, 'o', 0, 0, 0, 'k', 0, 0, 0};
        RosMessage m = decoded(d.decode(bytes));
        assertEquals(0, ((RosMessage) m.get("e")).fieldCount());
        assertArrayEquals(new boolean[]{true, false}, (boolean[]) m.get("flags"));
        assertEquals("ok", m.get("w"));
    }

    @Test
    void theHeaderIsChecked() throws Exception {
        CdrDecoder d = real("geometry_msgs/msg/Pose2D");
        byte[] pose = golden("geometry_msgs.msg.Pose2D.cdr");
        assertEquals("a CDR message of 3 bytes is shorter than its 4-byte header", refusal(d.decode(new byte[]{0, 1, 0})));
        byte[] pl = pose.clone();
        pl[1] = 3;
        assertEquals("parameter-list CDR (PL_CDR_LE) is not supported; ROS 2 messages are plain CDR", refusal(d.decode(pl)));
        pl[1] = 2;
        assertEquals("parameter-list CDR (PL_CDR_BE) is not supported; ROS 2 messages are plain CDR", refusal(d.decode(pl)));
        pl[1] = 7;
        assertEquals("encapsulation 00 07 is not CDR_BE (00 00) or CDR_LE (00 01) (XCDR2 is not supported)",
                refusal(d.decode(pl)));
        assertEquals(1.0, decoded(d.decode(pose)).get("x"));
    }

    @Test
    void aMessageShorterThanItsDefinitionSaysWhere() throws Exception {
        byte[] pose = golden("geometry_msgs.msg.Pose2D.cdr");
        assertEquals("the message ends at byte 24 where theta needs 8 bytes for float64 (at byte 20)",
                refusal(real("geometry_msgs/msg/Pose2D").decode(pose, 0, 24)));
    }

    @Test
    void hugeClaimedLengthsCostNothing() throws Exception {
        byte[] joints = golden("sensor_msgs.msg.JointState.cdr");
        CdrDecoder d = real("sensor_msgs/msg/JointState");
        ByteBuffer b = ByteBuffer.wrap(joints).order(ByteOrder.LITTLE_ENDIAN);
        // the name sequence's count follows the header (stamp 8 bytes, frame_id "map": 4 + 4)
        int countAt = 4 + 8 + 8;
        assertEquals(24, b.getInt(countAt));
        for (int claim : new int[]{-1, Integer.MAX_VALUE, 1 << 20, 1000}) {
            byte[] bad = joints.clone();
            ByteBuffer.wrap(bad).order(ByteOrder.LITTLE_ENDIAN).putInt(countAt, claim);
            String reason = refusal(d.decode(bad));
            assertTrue(reason.startsWith("name"), reason);
        }
        byte[] bad = joints.clone();
        ByteBuffer.wrap(bad).order(ByteOrder.LITTLE_ENDIAN).putInt(countAt, 0x7FFFFFFF);
        assertEquals("name needs 2147483647 elements (at least 8589934588 bytes) but " + (joints.length - countAt - 4)
                + " bytes are left", refusal(d.decode(bad)));
        // a string's length larger than the message
        byte[] str = joints.clone();
        ByteBuffer.wrap(str).order(ByteOrder.LITTLE_ENDIAN).putInt(4 + 8, -2);
        assertEquals("frame_id: a string of 4294967294 bytes but " + (joints.length - 16) + " bytes are left",
                refusal(d.decode(str)));
        // a fixed array the message cannot hold is refused before it is made
        assertTrue(refusal(decoder("t/msg/F", "float64[100000000] x\n").decode(new byte[]{0, 1, 0, 0, 1, 2, 3, 4}))
                .startsWith("x needs 100000000 elements"));
    }

    @Test
    void dataNestedDeeperThanTheLimitIsRefusedNotAStackOverflow() {
        CdrDecoder d = decoder("t/msg/Tree", "Tree[] children\n");
        int levels = 200;
        ByteBuffer b = ByteBuffer.allocate(4 + 4 * levels + 4).order(ByteOrder.LITTLE_ENDIAN);
        b.put(new byte[]{0, 1, 0, 0});
        for (int i = 0; i < levels; i++) {
            b.putInt(1);
        }
        b.putInt(0);
        assertEquals("t/msg/Tree nests deeper than 64 levels", refusal(d.decode(b.array())));
        ByteBuffer shallow = ByteBuffer.allocate(16).order(ByteOrder.LITTLE_ENDIAN).put(new byte[]{0, 1, 0, 0})
                .putInt(1).putInt(1).putInt(0);
        assertEquals("{children: [{children: [{children: []}]}]}", decoded(d.decode(shallow.array())).line(100));
    }

    @Test
    void offsetAndLengthSelectTheMessage() throws Exception {
        byte[] pose = golden("geometry_msgs.msg.Pose2D.cdr");
        byte[] framed = new byte[pose.length + 10];
        System.arraycopy(pose, 0, framed, 7, pose.length);
        assertEquals(0.5, decoded(real("geometry_msgs/msg/Pose2D").decode(framed, 7, pose.length)).get("theta"));
        assertEquals("no message: 32 bytes from 7 of " + framed.length,
                refusal(real("geometry_msgs/msg/Pose2D").decode(framed, 7, 32)));
    }
}
