package touchline.security;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The tag and trailer against the golden vector that the firmware's test_auth.c also checks
 * (HMAC-SHA-256, trailer version 2; computed independently with Python's hmac: key 00 01 … 1f, robot 3, counter 0x0123456789abcdef,
 * payload "hello", console → robot for the robot's boot 7), and every way a datagram is refused.
 */
class MessageTagTest {

    static TeamKey goldenKey() {
        byte[] k = new byte[32];
        for (int i = 0; i < 32; i++) {
            k[i] = (byte) i;
        }
        return new TeamKey(k);
    }

    private static final byte[] HELLO = "hello".getBytes(StandardCharsets.US_ASCII);

    @Test
    void goldenVectorMatchesTheFirmwareAndPython() {
        TeamKey key = goldenKey();
        assertEquals("630dcd29", key.idHex());
        MessageTag tag = new MessageTag(key);
        assertEquals("f89ae0adf649e6d7c578140cb79a8a5f",
                HexFormat.of().formatHex(tag.tag(MessageTag.toRobot(7), 3, 0x0123456789abcdefL, HELLO, 0, 5)));
        assertEquals("6706b936efe762f0098cae1da3259ceb",
                HexFormat.of().formatHex(tag.tag(MessageTag.toRobot(8), 3, 0x0123456789abcdefL, HELLO, 0, 5)),
                "the robot's next boot: another tag");
        assertEquals("5c6b4099c5658288dfe02f50628dca73",
                HexFormat.of().formatHex(tag.tag(MessageTag.FROM_ROBOT, 3, 0x0123456789abcdefL, HELLO, 0, 5)));
        assertEquals("034d61ffbcc87a27491f2702071b4bdb",
                HexFormat.of().formatHex(tag.tag(MessageTag.toRobot(7), 3, 0x0123456789abcdefL, HELLO, 0, 0)));
    }

    @Test
    void trailerLayoutIsMagicKeyIdCounterTag() {
        byte[] d = new MessageTag(goldenKey()).append(MessageTag.toRobot(7), 3, 0x0123456789abcdefL, HELLO);
        assertEquals("68656c6c6f" + "544c4132" + "630dcd29" + "0123456789abcdef" + "f89ae0adf649e6d7c578140cb79a8a5f",
                HexFormat.of().formatHex(d));
        assertEquals(new Trailer.Present(5, 0x0123456789abcdefL), Trailer.of(d));
    }

    @Test
    void refusesNoTagCutTagOtherKeyOtherRobotOtherDirectionAndChangedBytes() {
        MessageTag tag = new MessageTag(goldenKey());
        byte[] good = tag.append(MessageTag.toRobot(7), 3, 42, HELLO);
        assertEquals(MessageTag.Check.OK, tag.check(MessageTag.toRobot(7), 3, good, Trailer.of(good)));
        assertEquals(MessageTag.Check.NO_TAG, tag.check(MessageTag.toRobot(7), 3, HELLO, Trailer.of(HELLO)));
        byte[] cut = Arrays.copyOf(good, good.length - 8);
        assertEquals(new Trailer.Truncated(24), Trailer.of(cut));
        assertEquals(MessageTag.Check.TRUNCATED, tag.check(MessageTag.toRobot(7), 3, cut, Trailer.of(cut)));
        assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.toRobot(7), 4, good, Trailer.of(good)));
        assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.toRobot(8), 3, good, Trailer.of(good)),
                "a request of the robot's boot 7 after it rebooted");
        assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.FROM_ROBOT, 3, good, Trailer.of(good)));
        byte[] changed = good.clone();
        changed[0] ^= 1;
        assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.toRobot(7), 3, changed, Trailer.of(changed)));
        byte[] counterChanged = good.clone();
        counterChanged[5 + 15] ^= 1;
        assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.toRobot(7), 3, counterChanged, Trailer.of(counterChanged)));
        byte[] other = new byte[32];
        other[0] = 1;
        byte[] foreign = new MessageTag(new TeamKey(other)).append(MessageTag.toRobot(7), 3, 42, HELLO);
        assertEquals(MessageTag.Check.WRONG_KEY, tag.check(MessageTag.toRobot(7), 3, foreign, Trailer.of(foreign)));
    }

    @Test
    void everyTagByteCountsAndOneInstanceChecksDatagramAfterDatagram() {
        MessageTag tag = new MessageTag(goldenKey()); // its MAC buffer is reused from check to check
        byte[] good = tag.append(MessageTag.FROM_ROBOT, 3, 0x0123456789abcdefL, HELLO);
        for (int i = 0; i < MessageTag.TAG_SIZE; i++) {
            byte[] flipped = good.clone();
            flipped[good.length - MessageTag.TAG_SIZE + i] ^= (byte) 0x80;
            assertEquals(MessageTag.Check.BAD_TAG, tag.check(MessageTag.FROM_ROBOT, 3, flipped, Trailer.of(flipped)),
                    "tag byte " + i);
            assertEquals(MessageTag.Check.OK, tag.check(MessageTag.FROM_ROBOT, 3, good, Trailer.of(good)));
        }
        assertEquals("5c6b4099c5658288dfe02f50628dca73",
                HexFormat.of().formatHex(tag.tag(MessageTag.FROM_ROBOT, 3, 0x0123456789abcdefL, HELLO, 0, 5)));
    }

    @Test
    void aVersionOneTrailerIsRecognisedStrippedAndNeverVerified() {
        // Touchline 0.5's trailer: the same layout behind "TLA1", its tag HMAC-SHA-512 (here the first
        // 16 bytes of HMAC-SHA-512 over the golden bytes, from Python's hmac): the payload ends before
        // it, and it is OUTDATED whatever its tag says, never OK.
        byte[] v1 = HexFormat.of().parseHex("68656c6c6f" + "544c4131" + "630dcd29" + "0123456789abcdef"
                + "d2303baa78365196afe9afe96adb6b79");
        assertEquals(new Trailer.Outdated(5), Trailer.of(v1));
        assertEquals(5, InboundVerifier.payloadLength(v1));
        assertEquals(MessageTag.Check.OUTDATED, new MessageTag(goldenKey()).check(MessageTag.FROM_ROBOT, 3, v1, Trailer.of(v1)));
        byte[] plain = "TLA1 and TLA2 early in a payload that goes on well past a trailer's 32 bytes".getBytes(StandardCharsets.US_ASCII);
        assertEquals(new Trailer.Absent(), Trailer.of(plain));
        assertEquals(plain.length, InboundVerifier.payloadLength(plain));
    }

    @Test
    void keysOfTheWrongLengthAreRefusedAndNeverPrinted() {
        assertThrows(IllegalArgumentException.class, () -> new TeamKey(new byte[16]));
        TeamKey key = goldenKey();
        assertFalse(key.toString().contains(key.secretHex()));
        assertTrue(key.toString().contains("630dcd29"));
    }
}
