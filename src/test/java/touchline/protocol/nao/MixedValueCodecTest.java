package touchline.protocol.nao;

import com.google.protobuf.ByteString;
import org.junit.jupiter.api.Test;
import touchline.proto.Nao.MixedValue;

import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class MixedValueCodecTest {

    private final MixedValueCodec codec = new MixedValueCodec();

    private static String hex(MixedValue v) {
        return HexFormat.of().formatHex(v.toByteArray());
    }

    @Test
    void everyScalarTypeHasItsGoldenBytesAndComesBack() {
        assertEquals("0a026869", hex(codec.encode("hi")));
        assertEquals("102a", hex(codec.encode(42)));
        assertEquals("10ffffffff0f", hex(codec.encode(0xFFFF_FFFFL)));
        assertEquals("1d0000003f", hex(codec.encode(0.5f)));
        assertEquals("1d0000003f", hex(codec.encode(0.5d)));
        assertEquals("22020102", hex(codec.encode(new byte[] {1, 2})));
        assertEquals("2801", hex(codec.encode(true)));
        assertEquals("2800", hex(codec.encode(false)));
        assertEquals("", hex(codec.encode(null)));

        assertEquals("hi", codec.decode(codec.encode("hi")));
        assertEquals(42L, codec.decode(codec.encode(42)));
        assertEquals(4294967295L, codec.decode(codec.encode(0xFFFF_FFFFL)), "the wire int is unsigned");
        assertEquals(0.5f, codec.decode(codec.encode(0.5f)));
        assertArrayEquals(new byte[] {1, 2}, (byte[]) codec.decode(codec.encode(new byte[] {1, 2})));
        assertEquals(true, codec.decode(codec.encode(true)));
        assertEquals(false, codec.decode(codec.encode(false)));
        assertEquals(List.of(), codec.decode(MixedValue.getDefaultInstance()), "empty = empty array");
    }

    @Test
    void nestedArraysRoundTrip() {
        List<Object> value = List.of("HeadYaw", List.of(0.5f, List.of(1L, true, "x")), List.of());
        MixedValue wire = codec.encode(value);
        // [ {string HeadYaw}, {array [ {float 0.5}, {array [ {int 1}, {bool}, {string x} ]} ]}, {} ]
        assertEquals("3209" + "0a0748656164596177" + "3216" + "3205" + "1d0000003f" + "320d"
                + "32021001" + "32022801" + "32030a0178" + "3200", hex(wire));
        assertEquals(value, codec.decode(wire));
    }

    @Test
    void negativeIntsAndUnknownTypesAreRejectedWithAReason() {
        MixedValueException e = assertThrows(MixedValueException.class, () -> codec.encode(-1));
        assertTrue(e.getMessage().contains("unsigned"), e.getMessage());
        assertThrows(MixedValueException.class, () -> codec.encode(1L << 32));
        assertThrows(MixedValueException.class, () -> codec.encode(new Object()));
    }

    @Test
    void aValueWithTwoFieldsSetIsRejected() {
        MixedValue both = MixedValue.newBuilder().setString("a").setInt(1).build();
        assertThrows(MixedValueException.class, () -> codec.decode(both));
        MixedValue binaryAndArray = MixedValue.newBuilder().setBinary(ByteString.EMPTY)
                .addArray(MixedValue.getDefaultInstance()).build();
        assertThrows(MixedValueException.class, () -> codec.decode(binaryAndArray));
    }

    @Test
    void depthIsLimitedBothWays() {
        MixedValueCodec shallow = new MixedValueCodec(3);
        Object ok = List.of(List.of("deep enough"));
        assertEquals(ok, shallow.decode(shallow.encode(ok)));
        Object tooDeep = List.of(List.of(List.of("x")));
        assertThrows(MixedValueException.class, () -> shallow.encode(tooDeep));
        assertThrows(MixedValueException.class, () -> shallow.decode(codec.encode(tooDeep)));

        MixedValue v = MixedValue.newBuilder().setString("bottom").build();
        for (int i = 0; i < 60; i++) {
            v = MixedValue.newBuilder().addArray(v).build();
        }
        MixedValue hostile = v;
        MixedValueException e = assertThrows(MixedValueException.class, () -> codec.decode(hostile));
        assertTrue(e.getMessage().contains("32"), e.getMessage());
    }

    @Test
    void formatShowsTypes() {
        assertEquals("[\"a\", 1, 0.5f, true, <binary 3 bytes>, []]",
                MixedValueCodec.format(List.of("a", 1L, 0.5f, true, new byte[3], List.of())));
    }
}
