package touchline.model;

import com.google.protobuf.ByteString;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class Utf8NamesTest {

    private static ByteString utf8(String s) {
        return ByteString.copyFrom(s.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void aNameSeenAgainIsTheSameStringAsTheFirstTime() {
        Utf8Names names = new Utf8Names();
        String first = names.of(utf8("ball.distance"));
        assertEquals("ball.distance", first);
        assertSame(first, names.of(utf8("ball.distance")), "a fresh copy of the same bytes finds the decoded name");
        assertEquals("ßall → 球", names.of(utf8("ßall → 球")));
    }

    @Test
    void staysBoundedAndCorrectAfterManyDistinctNames() {
        Utf8Names names = new Utf8Names(64);
        for (int i = 0; i < 10_000; i++) {
            String name = "series" + i;
            assertEquals(name, names.of(utf8(name)));
            assertTrue(names.size() <= 64, "held " + names.size() + " names after " + (i + 1));
        }
        // names held before the table started afresh are decoded again, and right
        assertEquals("series0", names.of(utf8("series0")));
        assertEquals("series9999", names.of(utf8("series9999")));
        assertThrows(IllegalArgumentException.class, () -> new Utf8Names(0));
    }

    @Test
    void invalidUtf8IsDecodedAsTheMessagesOwnGetterDecodesIt() throws Exception {
        Utf8Names names = new Utf8Names();
        for (byte[] bad : new byte[][] {{(byte) 0xff, 'a'}, {(byte) 0xc3}, {'x', (byte) 0xe2, (byte) 0x82}}) {
            byte[] wire = Fumanoid.DebugText.newBuilder().setOptionBytes(ByteString.copyFrom(bad)).build().toByteArray();
            String viaGetter = Fumanoid.DebugText.parseFrom(wire).getOption();
            assertEquals(viaGetter, names.of(ByteString.copyFrom(bad)));
            assertEquals(viaGetter, names.optionOf(Fumanoid.DebugText.parseFrom(wire)));
        }
    }

    @Test
    void theOptionOfDataMessagesOursAndTeams() {
        Utf8Names names = new Utf8Names();
        assertEquals("demo.plotter", names.optionOf(Fumanoid.DebugPlot.newBuilder().setOption("demo.plotter").build()));
        assertEquals("havimo.region", names.optionOf(Fumanoid.RegionGrowing.newBuilder().setOption("havimo.region").build()));
        assertNull(names.optionOf(Fumanoid.DebugText.newBuilder().setText("no option").buildPartial()));
        assertNull(names.optionOf(Fumanoid.Status.getDefaultInstance()), "a status has no option field");
    }
}
