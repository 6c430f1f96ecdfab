package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;

/**
 * Decodes return ("RGrt") packets keyed on magic, version byte and exact length, and checks
 * their fields the way GameController3 and the HSL GameController do: player numbers in range,
 * fallen 0/1, no NaN in pose, ball age or ball (infinity passes, as there). Anything else is a
 * rejection with a reason, never an exception. A decoder for version 4 alone gives the verdicts
 * of the official SPL/HSL parser, which checks length, header, version, player, fallen, pose,
 * ball age and ball in that order (an 8-byte HL v2 packet is then of the wrong length).
 */
public final class ReturnPacketDecoder {

    /** Highest player number accepted in v1/v2 packets (HL MAX_NUM_PLAYERS). */
    public static final int MAX_PLAYER_V2 = 11;
    /** Highest player number accepted in v4 packets (SPL MAX_NUM_PLAYERS). */
    public static final int MAX_PLAYER_V4 = 20;

    private final boolean onlyV4;

    /** Accepts versions 1, 2 and 4. */
    public ReturnPacketDecoder() {
        this(false);
    }

    /** @param onlyV4 accept version 4 alone, as the SPL (2022–) and HSL GameControllers do */
    public ReturnPacketDecoder(boolean onlyV4) {
        this.onlyV4 = onlyV4;
    }

    public Decoded<ReturnPacket> decode(byte[] datagram) {
        if (onlyV4) {
            return decodeV4(datagram);
        }
        if (datagram == null || datagram.length < 5) {
            return Decoded.rejected(DecodeFailure.WRONG_LENGTH,
                    "too short for a return packet: " + (datagram == null ? 0 : datagram.length) + " bytes");
        }
        int version = datagram[4] & 0xFF;
        return switch (version) {
            case 1 -> decodeV1(datagram);
            case 2 -> decodeV2(datagram);
            case 4 -> decodeV4(datagram);
            default -> {
                Decoded<ReturnPacket> bad = WireChecks.checkFrame(datagram, datagram.length, WireChecks.RETURN_MAGIC);
                yield bad != null ? bad : WireChecks.wrongVersion(2, version);
            }
        };
    }

    private static Decoded<ReturnPacket> decodeV1(byte[] d) {
        Decoded<ReturnPacket> bad = WireChecks.checkFrame(d, ReturnPacket.V1.SIZE, WireChecks.RETURN_MAGIC);
        if (bad != null) {
            return bad;
        }
        ByteBuffer b = WireChecks.reader(d);
        b.position(4);
        long version = b.getInt() & 0xFFFFFFFFL;
        if (version != 1) {
            return WireChecks.wrongVersion(1, version);
        }
        int team = WireChecks.u16(b);
        int player = WireChecks.u16(b);
        long message = b.getInt() & 0xFFFFFFFFL;
        return checked(new ReturnPacket.V1(team, player, (int) Math.min(message, Integer.MAX_VALUE)), MAX_PLAYER_V2,
                message);
    }

    private static Decoded<ReturnPacket> decodeV2(byte[] d) {
        Decoded<ReturnPacket> bad = WireChecks.checkFrame(d, ReturnPacket.V2.SIZE, WireChecks.RETURN_MAGIC);
        if (bad != null) {
            return bad;
        }
        int message = d[7] & 0xFF;
        return checked(new ReturnPacket.V2(d[5] & 0xFF, d[6] & 0xFF, message), MAX_PLAYER_V2, message);
    }

    private static Decoded<ReturnPacket> checked(ReturnPacket p, int maxPlayer, long message) {
        if (p.player() < 1 || p.player() > maxPlayer) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, "player " + p.player() + " not in 1.." + maxPlayer);
        }
        if (message > ReturnPacket.GAME_INTERRUPTION_READY) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, "unknown message " + message);
        }
        return Decoded.ok(p);
    }

    private static Decoded<ReturnPacket> decodeV4(byte[] d) {
        Decoded<ReturnPacket> bad = WireChecks.checkFrame(d, ReturnPacket.V4.SIZE, WireChecks.RETURN_MAGIC);
        if (bad != null) {
            return bad;
        }
        if (d[4] != 4) {
            return WireChecks.wrongVersion(4, d[4] & 0xFF);
        }
        ByteBuffer b = WireChecks.reader(d);
        b.position(5);
        int player = WireChecks.u8(b);
        int team = WireChecks.u8(b);
        int fallen = WireChecks.u8(b);
        if (player < 1 || player > MAX_PLAYER_V4) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD,
                    "invalid player number: " + player + " not in 1.." + MAX_PLAYER_V4);
        }
        if (fallen > 1) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, "invalid fallen: must be 0 or 1, got " + fallen);
        }
        float[] f = new float[6];
        for (int i = 0; i < f.length; i++) {
            f[i] = b.getFloat();
        }
        String nan = Float.isNaN(f[0]) || Float.isNaN(f[1]) || Float.isNaN(f[2]) ? "invalid pose"
                : Float.isNaN(f[3]) ? "invalid ball age"
                : Float.isNaN(f[4]) || Float.isNaN(f[5]) ? "invalid ball" : null;
        if (nan != null) {
            return Decoded.rejected(DecodeFailure.INVALID_FIELD, nan + ": NaN");
        }
        return Decoded.ok(new ReturnPacket.V4(player, team, fallen, f[0], f[1], f[2], f[3], f[4], f[5]));
    }
}
