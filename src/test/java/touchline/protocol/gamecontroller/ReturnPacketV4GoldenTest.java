package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The robots' return packet v4 gets the verdict of the official HSL GameController's parser
 * (7.0.0-rc.3, identical in 6.0.1) for each of the 15 packets of the golden data.
 */
class ReturnPacketV4GoldenTest {

    private final HslGolden golden = new HslGolden("hsl20");
    private final ReturnPacketDecoder official = new ReturnPacketDecoder(true);

    /** The official parser's bail messages and the failure each is counted as here. */
    private static final Map<String, DecodeFailure> FAILURES = Map.of(
            "wrong length", DecodeFailure.WRONG_LENGTH,
            "wrong header", DecodeFailure.WRONG_MAGIC,
            "wrong version", DecodeFailure.WRONG_VERSION,
            "invalid player number", DecodeFailure.INVALID_FIELD,
            "invalid fallen", DecodeFailure.INVALID_FIELD,
            "invalid pose", DecodeFailure.INVALID_FIELD,
            "invalid ball age", DecodeFailure.INVALID_FIELD,
            "invalid ball", DecodeFailure.INVALID_FIELD);

    @Test
    void everyPacketGetsTheOfficialVerdict() {
        assertEquals(15, golden.returnVerdicts.size());
        golden.returnVerdicts.forEach((file, verdict) -> {
            Decoded<ReturnPacket> d = official.decode(golden.bytes("return/" + file));
            if (verdict.startsWith("accepted")) {
                assertTrue(d.isOk(), file + ": " + d);
            } else {
                String reason = verdict.substring("rejected: ".length());
                assertEquals(FAILURES.get(reason), d.failure(), file + ": " + d);
                if (d.failure() == DecodeFailure.INVALID_FIELD) {
                    assertTrue(d.detail().startsWith(reason + ":"), file + ": " + d.detail());
                }
            }
        });
    }

    @Test
    void acceptedPacketsCarryTheirFields() {
        ReturnPacket.V4 r01 = (ReturnPacket.V4) official.decode(golden.bytes("return/r01-team5-player1-upright.bin")).value();
        assertEquals(new ReturnPacket.V4(1, 5, 0, 1000f, -500f, 1.5f, 0.5f, 250f, 30f), r01);
        ReturnPacket.V4 r02 = (ReturnPacket.V4) official.decode(golden.bytes("return/r02-team14-player20-fallen-no-ball.bin")).value();
        assertEquals(20, r02.player());
        assertEquals(1, r02.fallen());
        assertEquals(-1f, r02.ballAge());
        ReturnPacket.V4 r12 = (ReturnPacket.V4) official.decode(golden.bytes("return/r12-infinite-ball-age.bin")).value();
        assertEquals(Float.POSITIVE_INFINITY, r12.ballAge());
        for (String file : golden.returnVerdicts.keySet()) {
            Decoded<ReturnPacket> d = official.decode(golden.bytes("return/" + file));
            if (d.isOk()) {
                assertEquals(java.util.HexFormat.of().formatHex(golden.bytes("return/" + file)),
                        java.util.HexFormat.of().formatHex(d.value().encode()), file);
            }
        }
    }

    @Test
    void theConsolesOwnDecoderStillTakesTheOlderVersions() {
        byte[] hlV2 = golden.bytes("return/r15-hl-v2-8-bytes.bin");
        assertEquals(DecodeFailure.WRONG_LENGTH, official.decode(hlV2).failure());
        assertTrue(new ReturnPacketDecoder().decode(hlV2).isOk(), "an HL field's v2 packet");
    }
}
