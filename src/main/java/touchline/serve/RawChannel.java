package touchline.serve;

import touchline.transport.Envelope;

import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * A channel of envelopes without a decoded message, served as their bytes so another
 * Touchline rebuilds them and decodes them itself, as from the field: GameController packets,
 * NAO camera frames and replies, team messages ({@link #RAW}: the datagram as heard, encoding
 * {@code application/octet-stream}); and datagrams that did not decode ({@link #MALFORMED}:
 * the reason and the bytes, encoding {@code application/x-touchline-malformed}, as the
 * recorder writes them: a uint16 little-endian length, the reason in UTF-8, the bytes). No
 * schema: Foxglove and Lichtblick list these channels and leave them alone.
 */
enum RawChannel implements ChannelPayloads {

    RAW("application/octet-stream", "raw"),
    MALFORMED("application/x-touchline-malformed", "malformed");

    private final String encoding;
    private final String served;

    RawChannel(String encoding, String served) {
        this.encoding = encoding;
        this.served = served;
    }

    /** How {@code e} is served raw, or null when it goes out as protobuf (it has a decoded message). */
    static RawChannel of(Envelope e) {
        if (e.error() != null) {
            return MALFORMED;
        }
        return e.message() == null ? RAW : null;
    }

    String encoding() {
        return encoding;
    }

    /** The recording's channel metadata and {@code touchline.served}: {@code raw} or {@code malformed}. */
    Map<String, String> metadata(Map<String, String> recorded) {
        Map<String, String> m = new LinkedHashMap<>(recorded);
        m.put(ChannelSchema.SERVED_KEY, served);
        return m;
    }

    @Override
    public byte[] payload(Envelope e) {
        if (this == RAW) {
            return e.raw();
        }
        byte[] reason = e.error().getBytes(StandardCharsets.UTF_8);
        int n = Math.min(reason.length, 0xFFFF);
        byte[] raw = e.raw() == null ? new byte[0] : e.raw();
        byte[] out = new byte[2 + n + raw.length];
        out[0] = (byte) n;
        out[1] = (byte) (n >>> 8);
        System.arraycopy(reason, 0, out, 2, n);
        System.arraycopy(raw, 0, out, 2 + n, raw.length);
        return out;
    }
}
