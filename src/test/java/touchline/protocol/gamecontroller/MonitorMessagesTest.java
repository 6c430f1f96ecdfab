package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.Arrays;
import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The monitor side of an HSL GameController: the "RGTr" request and forwarded return packets on 3940. */
class MonitorMessagesTest {

    private final HslGolden golden = new HslGolden("hsl20");
    private final ForwardedReturnPacket.Decoder forwarded = new ForwardedReturnPacket.Decoder();

    @Test
    void theRequestIsRgtrAndVersionZero() {
        MonitorRequest request = new MonitorRequest();
        assertEquals("5247547200", HexFormat.of().formatHex(request.encode()));
        assertTrue(request.decode(request.encode()).isOk());
        assertEquals(DecodeFailure.WRONG_LENGTH, request.decode(Arrays.copyOf(request.encode(), 6)).failure());
        assertEquals(DecodeFailure.WRONG_VERSION, request.decode(new byte[]{'R', 'G', 'T', 'r', 1}).failure());
        assertEquals(DecodeFailure.WRONG_MAGIC, request.decode(new byte[]{'R', 'G', 'T', 'D', 0}).failure());
    }

    private byte[] prefixed(int a, int b, int c, int d, String returnFile) {
        byte[] robot = golden.bytes("return/" + returnFile);
        byte[] out = new byte[4 + robot.length];
        out[0] = (byte) a;
        out[1] = (byte) b;
        out[2] = (byte) c;
        out[3] = (byte) d;
        System.arraycopy(robot, 0, out, 4, robot.length);
        return out;
    }

    @Test
    void aForwardedPacketIsTheRobotsAddressAndItsPacket() {
        byte[] bytes = prefixed(10, 0, 5, 12, "r01-team5-player1-upright.bin");
        assertEquals(36, bytes.length);
        Decoded<ForwardedReturnPacket> d = forwarded.decode(bytes);
        assertTrue(d.isOk(), d.toString());
        assertEquals("10.0.5.12", d.value().robotHost());
        assertEquals(5, d.value().packet().team());
        assertEquals(1, d.value().packet().player());
        assertArrayEquals(bytes, d.value().encode());
    }

    @Test
    void aBadAddressPrefixOrABadPacketIsAReason() {
        for (int[] bad : new int[][]{{0, 0, 0, 0}, {255, 255, 255, 255}, {239, 0, 0, 1}, {224, 1, 2, 3}}) {
            Decoded<ForwardedReturnPacket> d = forwarded.decode(prefixed(bad[0], bad[1], bad[2], bad[3],
                    "r01-team5-player1-upright.bin"));
            assertEquals(DecodeFailure.INVALID_FIELD, d.failure(), Arrays.toString(bad));
            assertTrue(d.detail().contains("not a robot's unicast IPv4 address"), d.detail());
        }
        assertEquals(DecodeFailure.WRONG_LENGTH, forwarded.decode(golden.bytes("return/r01-team5-player1-upright.bin"))
                .failure(), "a packet without its prefix");
        assertEquals(DecodeFailure.WRONG_LENGTH, forwarded.decode(prefixed(10, 0, 5, 12, "r13-length-31.bin")).failure());
        Decoded<ForwardedReturnPacket> nan = forwarded.decode(prefixed(10, 0, 5, 12, "r09-nan-pose.bin"));
        assertEquals(DecodeFailure.INVALID_FIELD, nan.failure());
        assertTrue(nan.detail().contains("invalid pose"), nan.detail());
        assertTrue(forwarded.decode(prefixed(127, 0, 0, 1, "r02-team14-player20-fallen-no-ball.bin")).isOk(),
                "a simulated robot on the GameController's host");
    }
}
