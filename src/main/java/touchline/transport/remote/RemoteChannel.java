package touchline.transport.remote;

import com.google.protobuf.CodedOutputStream;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.DescriptorValidationException;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import com.google.protobuf.InvalidProtocolBufferException;
import org.json.JSONObject;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageResult;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.util.Base64;
import java.util.HashMap;
import java.util.Map;

/**
 * One robot channel of the remote Touchline and how its payloads become envelopes again. The
 * channel's metadata (the recording's {@code touchline.*} keys plus {@code touchline.served})
 * says whose and what the messages are; a FUmanoids payload is put back into a
 * {@code fumanoid.Message} of the channel's robot, framed as the robot framed it, and decoded
 * by the same {@link MessageCodec} as a datagram from the field, so every view sees the types
 * it sees live. Other protobuf channels are decoded with the advertised schema.
 */
final class RemoteChannel implements StreamChannel {

    private final int id;
    private final String topic;
    private final Direction direction;
    private final Channel channel;
    private final InetSocketAddress peer;
    private final int robotId;
    private final String kind;
    private final Framing framing;      // null: not a FUmanoids datagram
    private final int extensionNumber;  // > 0: the payload is this extension's message
    private final Descriptor type;      // for channels that are not FUmanoids datagrams
    private final MessageCodec codec;
    private final FrameCodec frames;
    private final boolean bytes;        // the payload is the datagram's bytes (or MALFORMED's reason and bytes)
    private final boolean malformed;

    /** {@code touchline.served} of a channel of bytes: the datagram as heard, or one that did not decode. */
    static final String RAW = "raw";
    static final String MALFORMED = "malformed";

    private RemoteChannel(int id, String topic, Map<String, String> m, MessageCodec codec, FrameCodec frames,
                          Descriptor type, boolean malformed) {
        this.id = id;
        this.topic = topic;
        this.direction = Direction.valueOf(required(m, "touchline.direction"));
        this.channel = Channel.valueOf(required(m, "touchline.channel"));
        this.peer = peer(m.get("touchline.peer"));
        this.robotId = Integer.parseInt(required(m, "touchline.robot"));
        this.kind = required(m, "touchline.kind");
        String f = m.get("touchline.framing");
        this.framing = channel == Channel.FUMANOID && "payload".equals(m.get("touchline.layout")) && f != null
                ? Framing.valueOf(f) : null;
        this.codec = codec;
        this.frames = frames;
        this.type = type;
        this.bytes = RAW.equals(m.get("touchline.served")) || MALFORMED.equals(m.get("touchline.served"));
        this.malformed = malformed;
        if (bytes) {
            this.extensionNumber = 0;
            return;
        }
        if (framing != null && "extension".equals(m.get("touchline.served"))) {
            FieldDescriptor ext = codec.kinds().byName(kind).orElseThrow(() -> new IllegalArgumentException(
                    "kind " + kind + " is not known here (load the team's schema with --proto)"));
            this.extensionNumber = ext.getNumber();
        } else {
            this.extensionNumber = 0;
        }
        if (framing == null && type == null) {
            throw new IllegalArgumentException("neither a FUmanoids datagram nor a protobuf schema");
        }
    }

    /**
     * The channel an Advertise op lists, or IllegalArgumentException saying why it cannot be
     * rebuilt (no Touchline metadata: a JSON state channel, or another server's channel).
     */
    static RemoteChannel of(JSONObject advertised, MessageCodec codec, FrameCodec frames) {
        JSONObject meta = advertised.optJSONObject("metadata");
        if (meta == null || !meta.has("touchline.kind")) {
            throw new IllegalArgumentException("no Touchline metadata");
        }
        Map<String, String> m = new HashMap<>();
        for (String k : meta.keySet()) {
            m.put(k, String.valueOf(meta.get(k)));
        }
        String served = m.get("touchline.served");
        if (RAW.equals(served) || MALFORMED.equals(served)) {
            try {
                return new RemoteChannel(advertised.getInt("id"), advertised.optString("topic"), m, codec, frames,
                        null, MALFORMED.equals(served));
            } catch (RuntimeException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
        }
        if (!"protobuf".equals(advertised.optString("encoding"))) {
            throw new IllegalArgumentException("encoding " + advertised.optString("encoding"));
        }
        Descriptor type = Channel.FUMANOID.name().equals(m.get("touchline.channel")) ? null
                : schema(advertised.optString("schema"), advertised.optString("schemaName"));
        try {
            return new RemoteChannel(advertised.getInt("id"), advertised.optString("topic"), m, codec, frames, type,
                    false);
        } catch (RuntimeException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    @Override
    public int id() {
        return id;
    }

    @Override
    public String topic() {
        return topic;
    }

    /** The envelope the remote console saw, rebuilt from one message's payload; received at {@code timeNanos} there. */
    @Override
    public Envelope rebuild(byte[] payload, long timeNanos) throws IOException {
        long micros = timeNanos / 1000;
        if (bytes) {
            return malformed ? malformed(payload, micros) : new Envelope(micros, direction, channel, peer, robotId, kind,
                    null, payload, null, Origin.REMOTE);
        }
        if (framing == null) {
            return new Envelope(micros, direction, channel, peer, robotId, kind, DynamicMessage.parseFrom(type, payload),
                    payload, null, Origin.REMOTE);
        }
        byte[] message = extensionNumber > 0 ? wrap(payload) : payload;
        MessageResult result = codec.decode(message);
        if (result instanceof MessageResult.Malformed bad) {
            throw new IOException(bad.reason());
        }
        MessageResult.Decoded d = (MessageResult.Decoded) result;
        return new Envelope(micros, direction, channel, peer, robotId, d.kind(), d.message(),
                frames.encode(framing, message), null, Origin.REMOTE);
    }

    /** A datagram that did not decode there: a uint16 little-endian length, the reason in UTF-8, the bytes. */
    private Envelope malformed(byte[] payload, long micros) throws IOException {
        int n = payload.length < 2 ? -1 : (payload[0] & 0xFF) | (payload[1] & 0xFF) << 8;
        if (n < 0 || 2 + n > payload.length) {
            throw new IOException("a malformed-datagram message of " + payload.length + " bytes is too short for its reason");
        }
        String reason = new String(payload, 2, n, java.nio.charset.StandardCharsets.UTF_8);
        byte[] raw = java.util.Arrays.copyOfRange(payload, 2 + n, payload.length);
        return new Envelope(micros, direction, channel, peer, robotId, kind, null, raw, reason, Origin.REMOTE);
    }

    /** The {@code fumanoid.Message} around an extension's payload: the sender's ID (field 1) and the extension. */
    private byte[] wrap(byte[] inner) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(inner.length + 16);
        CodedOutputStream out = CodedOutputStream.newInstance(bytes);
        out.writeInt32(1, direction == Direction.OUT ? MessageCodec.CONSOLE_ID : robotId);
        out.writeByteArray(extensionNumber, inner);
        out.flush();
        return bytes.toByteArray();
    }

    private static String required(Map<String, String> m, String key) {
        String v = m.get(key);
        if (v == null) {
            throw new IllegalArgumentException("no " + key + " in its metadata");
        }
        return v;
    }

    /** {@code 10.0.0.7:10001} or {@code unresolved:nao.local:5555}; never a name lookup. */
    static InetSocketAddress peer(String s) {
        return touchline.transport.PeerText.parse(s);
    }

    /** The advertised type from its self-contained FileDescriptorSet (dependencies first, as the recorder writes it). */
    static Descriptor schema(String base64, String name) {
        try {
            FileDescriptorSet set = FileDescriptorSet.parseFrom(Base64.getDecoder().decode(base64));
            Map<String, FileDescriptor> built = new HashMap<>();
            Descriptor found = null;
            for (FileDescriptorProto p : set.getFileList()) {
                FileDescriptor[] deps = p.getDependencyList().stream().map(built::get).toArray(FileDescriptor[]::new);
                FileDescriptor f = FileDescriptor.buildFrom(p, deps);
                built.put(p.getName(), f);
                String simple = name.startsWith(p.getPackage() + ".") ? name.substring(p.getPackage().length() + 1) : name;
                Descriptor d = f.findMessageTypeByName(simple);
                found = d != null ? d : found;
            }
            if (found == null) {
                throw new IllegalArgumentException("schema " + name + " is not in the advertised descriptor set");
            }
            return found;
        } catch (InvalidProtocolBufferException | DescriptorValidationException | IllegalArgumentException
                 | NullPointerException e) {
            throw new IllegalArgumentException("unreadable schema " + name + ": " + e.getMessage(), e);
        }
    }
}
