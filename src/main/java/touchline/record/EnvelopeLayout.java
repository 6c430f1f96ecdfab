package touchline.record;

import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * How an {@link Envelope} maps onto MCAP channels and message bytes, both ways. Everything
 * that is the same for many envelopes (direction, wire channel, peer, robot, kind, framing,
 * origin) lives in the MCAP channel's metadata, one channel per distinct combination; the message
 * holds only what varies:
 * <ul>
 * <li>{@link #PAYLOAD}: a well-framed FUmanoids datagram. The data is the protobuf
 *     {@code fumanoid.Message} behind the header (encoding {@code protobuf}, so other MCAP
 *     tools decode it); the header is rebuilt from the channel's framing on replay. A datagram
 *     that carried a team key's trailer (docs/security.md) is recorded so too, without the
 *     trailer: its tag and counter were checked when it arrived and mean nothing to a replay or
 *     another tool; a forged one has no message and is kept whole as {@link #RAW}.</li>
 * <li>{@link #RAW}: anything else that decoded or needs no decoding (GameController packets,
 *     NAO calls, camera JPEGs, link events): the exact bytes, encoding
 *     {@value #RAW_ENCODING}, no schema.</li>
 * <li>{@link #MALFORMED}: bytes that did not decode. The data is a uint16 little-endian
 *     length, the UTF-8 error text, then the exact bytes (encoding {@value #MALFORMED_ENCODING}).</li>
 * </ul>
 */
final class EnvelopeLayout {

    static final String PAYLOAD = "payload";
    static final String RAW = "raw";
    static final String MALFORMED = "malformed";

    static final String RAW_ENCODING = "application/octet-stream";
    static final String MALFORMED_ENCODING = "application/x-touchline-malformed";

    static final String KEY_DIRECTION = "touchline.direction";
    static final String KEY_CHANNEL = "touchline.channel";
    static final String KEY_PEER = "touchline.peer";
    static final String KEY_ROBOT = "touchline.robot";
    static final String KEY_KIND = "touchline.kind";
    static final String KEY_LAYOUT = "touchline.layout";
    static final String KEY_FRAMING = "touchline.framing";
    /** live, remote or replay ({@link Origin}); a file without it (before issue 38) holds live envelopes. */
    static final String KEY_ORIGIN = "touchline.origin";

    /** The per-channel facts of an envelope: the key its MCAP channel is found by. */
    record Key(Direction direction, Channel channel, InetSocketAddress peer, int robotId, String kind,
               String layout, Framing framing, Origin origin) {

        // Written out rather than the record's generated ones: this runs for every recorded
        // envelope, and the generated equals cost more than writing the message (cheap,
        // discriminating fields first; the peer's address last).
        @Override
        public boolean equals(Object o) {
            return o instanceof Key k && robotId == k.robotId && direction == k.direction && channel == k.channel
                    && framing == k.framing && origin == k.origin && kind.equals(k.kind) && layout.equals(k.layout)
                    && java.util.Objects.equals(peer, k.peer);
        }

        @Override
        public int hashCode() {
            int h = robotId * 31 + kind.hashCode();
            h = h * 31 + (channel.ordinal() * 4 + direction.ordinal()) * 4 + origin.ordinal();
            h = h * 31 + (peer == null ? 0 : peer.getPort());
            return h * 31 + layout.hashCode();
        }

        Map<String, String> metadata() {
            Map<String, String> m = new LinkedHashMap<>();
            m.put(KEY_DIRECTION, direction.name());
            m.put(KEY_CHANNEL, channel.name());
            if (peer != null) {
                m.put(KEY_PEER, formatPeer(peer));
            }
            m.put(KEY_ROBOT, Integer.toString(robotId));
            m.put(KEY_KIND, kind);
            m.put(KEY_LAYOUT, layout);
            if (framing != null) {
                m.put(KEY_FRAMING, framing.name());
            }
            m.put(KEY_ORIGIN, origin.name().toLowerCase(java.util.Locale.ROOT));
            return m;
        }

        /** e.g. /robot/3/status, /robot/3/out/debugOptionRequest, /gc/out/hl12, /nao/rpc, /robot/2/malformed. */
        String topic() {
            String robot = robotId == Envelope.NO_ROBOT ? "unknown" : Integer.toString(robotId);
            String dir = direction == Direction.OUT ? "/out" : "";
            String[] parts = switch (channel) {
                case FUMANOID -> new String[]{"/robot/" + robot, ""};
                case RELIABLE_STREAM -> new String[]{"/robot/" + robot, "/stream"};
                case GAMECONTROLLER -> new String[]{"/gc", ""};
                case NAO_RPC -> new String[]{"/nao", "/rpc"};
                case NAO_CAMERA -> new String[]{"/nao", "/camera"};
                case LINK_EVENT -> new String[]{"/link", ""};
                case TEAM_MESSAGE -> new String[]{"/team", ""};
                case FOREIGN -> new String[]{"/foreign", ""};
                case BRIDGE -> new String[]{"/bridge/" + robot, ""};
            };
            if (channel == Channel.BRIDGE) { // a bridged robot's topic as the robot names it, under its robot
                return parts[0] + (kind.startsWith("/") ? "" : "/") + kind.replaceAll("[^A-Za-z0-9_#./\\-]", "_")
                        + (layout.equals(MALFORMED) ? "/malformed" : "");
            }
            String name = kind.replaceAll("[^A-Za-z0-9_#.\\-]", "_");
            String topic = parts[0] + dir + parts[1];
            if (!parts[1].equals("/" + name)) {
                topic += "/" + name;
            }
            if (layout.equals(MALFORMED) && !name.contains("malformed")) {
                topic += "/malformed";
            }
            return topic;
        }

        String encoding() {
            return switch (layout) {
                case PAYLOAD -> "protobuf";
                case MALFORMED -> MALFORMED_ENCODING;
                default -> RAW_ENCODING;
            };
        }

        /** Throws IllegalArgumentException (saying which key) when the metadata is not a Touchline channel's. */
        static Key fromMetadata(Map<String, String> m) {
            for (String required : new String[]{KEY_DIRECTION, KEY_CHANNEL, KEY_ROBOT, KEY_KIND}) {
                if (m.get(required) == null) {
                    throw new IllegalArgumentException("no " + required + " in its metadata");
                }
            }
            String framing = m.get(KEY_FRAMING);
            if (PAYLOAD.equals(m.get(KEY_LAYOUT)) && framing == null) {
                throw new IllegalArgumentException("a payload channel without " + KEY_FRAMING);
            }
            return new Key(Direction.valueOf(m.get(KEY_DIRECTION)), Channel.valueOf(m.get(KEY_CHANNEL)),
                    parsePeer(m.get(KEY_PEER)), Integer.parseInt(m.get(KEY_ROBOT)), m.get(KEY_KIND),
                    m.getOrDefault(KEY_LAYOUT, RAW), framing == null ? null : Framing.valueOf(framing),
                    origin(m.getOrDefault(KEY_ORIGIN, "live")));
        }

        private static Origin origin(String word) {
            for (Origin o : Origin.values()) {
                if (o.name().toLowerCase(java.util.Locale.ROOT).equals(word)) {
                    return o;
                }
            }
            throw new IllegalArgumentException(KEY_ORIGIN + " is \"" + word + "\", not live, remote or replay");
        }
    }

    // No size limit on replay: the recorder kept whatever the transport accepted.
    private final FrameCodec frames = new FrameCodec(Integer.MAX_VALUE);

    /**
     * The channel key of {@code e}. PAYLOAD needs a header {@link FrameCodec} accepts and would
     * write identically (legacy flags and reserved bytes zero), so replay rebuilds it byte for
     * byte; the payload then starts at {@code key.framing().headerSize()}. Checked in place,
     * without copying, because this runs for every recorded datagram.
     */
    Key keyOf(Envelope e) {
        String layout = layoutOf(e);
        return key(e, layout, layout == PAYLOAD ? exactFraming(e.raw()) : null);
    }

    /** {@link #PAYLOAD}, {@link #RAW} or {@link #MALFORMED} (the constants themselves, comparable with ==). */
    static String layoutOf(Envelope e) {
        if (e.error() != null) {
            return MALFORMED;
        }
        if (e.channel() == Channel.FUMANOID && e.message() != null && exactFraming(e.raw()) != null) {
            return PAYLOAD;
        }
        return RAW;
    }

    /** Where a FUmanoids datagram's frame ends: before a team key's trailer, else at its end. */
    static int frameEnd(byte[] raw) {
        return touchline.security.InboundVerifier.payloadLength(raw);
    }

    /** The framing of {@code raw}'s frame (up to {@link #frameEnd}) when its header is the canonical one, else null. */
    static Framing exactFraming(byte[] raw) {
        int end = frameEnd(raw);
        if (end >= 2 && raw[0] == 0 && raw[1] == Framing.MESSAGE_TYPE) {
            if (end < 12 || lengthField(raw, 8) != end - 12) {
                return null;
            }
            for (int i = 2; i < 8; i++) {
                if (raw[i] != 0) {
                    return null;
                }
            }
            return Framing.LEGACY;
        }
        return end >= 4 && lengthField(raw, 0) == end - 4 ? Framing.LENGTH_PREFIX : null;
    }

    private static long lengthField(byte[] d, int at) {
        return ((long) (d[at] & 0xFF) << 24) | ((d[at + 1] & 0xFF) << 16) | ((d[at + 2] & 0xFF) << 8) | (d[at + 3] & 0xFF);
    }

    private static Key key(Envelope e, String layout, Framing framing) {
        return new Key(e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(), layout, framing, e.origin());
    }

    static byte[] malformedData(String error, byte[] raw) {
        byte[] text = error.getBytes(StandardCharsets.UTF_8);
        int n = Math.min(text.length, 0xFFFF);
        byte[] out = new byte[2 + n + raw.length];
        out[0] = (byte) n;
        out[1] = (byte) (n >>> 8);
        System.arraycopy(text, 0, out, 2, n);
        System.arraycopy(raw, 0, out, 2 + n, raw.length);
        return out;
    }

    /** Splits MALFORMED data into {error, raw}; null when the data is too short to be one. */
    static Object[] parseMalformed(byte[] data) {
        if (data.length < 2) {
            return null;
        }
        int n = (data[0] & 0xFF) | (data[1] & 0xFF) << 8;
        if (2 + n > data.length) {
            return null;
        }
        byte[] raw = new byte[data.length - 2 - n];
        System.arraycopy(data, 2 + n, raw, 0, raw.length);
        return new Object[]{new String(data, 2, n, StandardCharsets.UTF_8), raw};
    }

    byte[] frame(Framing framing, byte[] payload) {
        return frames.encode(framing, payload);
    }

    static String formatPeer(InetSocketAddress peer) {
        return touchline.transport.PeerText.format(peer);
    }

    static boolean isAddressLiteral(String host) {
        return touchline.transport.PeerText.isAddressLiteral(host);
    }

    /** A name written in a file from outside stays unresolved: opening a recording never causes a lookup. */
    static InetSocketAddress parsePeer(String s) {
        return touchline.transport.PeerText.parse(s);
    }
}
