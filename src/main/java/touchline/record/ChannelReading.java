package touchline.record;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.DynamicMessage;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.Message;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageResult;
import touchline.protocol.ros2.ChannelDecoders;
import touchline.protocol.ros2.ChannelDecoding;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.MessageDecoder;
import touchline.security.Authenticity;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.util.Map;
import java.util.function.Function;

/**
 * How the messages of one MCAP channel become Envelopes: a channel Touchline wrote
 * ({@link Touchline}, its metadata says everything), a channel another tool wrote whose
 * messages can still be shown ({@link Foreign}: protobuf with its schema in the file;
 * {@link Decoded}: ROS 2 CDR by its ros2msg/ros2idl definition, or JSON; {@link Bridged}: a
 * bridged robot's channel Touchline recorded in the robot's own encoding), or a channel whose
 * messages are skipped and counted, with the reason ({@link Skipped}: an encoding this reader
 * does not decode, such as flatbuffer, a definition or protobuf schema missing or unparsable). A foreign channel's bytes are never
 * decoded as FUmanoids protobuf unless its schema says they are {@code fumanoid.Message}.
 */
sealed interface ChannelReading {

    record Touchline(EnvelopeLayout.Key key) implements ChannelReading { }

    record Skipped(String topic, String encoding, String reason) implements ChannelReading { }

    /** Another tool's channel shown as {@link Channel#FOREIGN} envelopes named by its topic. */
    record Foreign(String topic, Function<byte[], Message> decoder) implements ChannelReading {

        Envelope envelope(long timeMicros, byte[] data) {
            return new Envelope(timeMicros, Direction.IN, Channel.FOREIGN, null, Envelope.NO_ROBOT, topic,
                    decoder == null ? null : decoder.apply(data), data, null);
        }
    }

    /**
     * Another tool's ROS 2 or JSON channel: {@link Channel#FOREIGN} envelopes named by its topic
     * carrying the decoded tree in {@link Envelope#ros()}; a message that does not fit its
     * definition is a malformed envelope with the decoder's reason.
     */
    record Decoded(String topic, MessageDecoder decoder) implements ChannelReading {

        Envelope envelope(long timeMicros, byte[] data) {
            DecodeResult r = decoder.decode(data);
            return new Envelope(timeMicros, Direction.IN, Channel.FOREIGN, null, Envelope.NO_ROBOT, topic, null, data,
                    r instanceof DecodeResult.Undecodable u ? u.reason() : null, Origin.LIVE, Authenticity.NOT_CHECKED,
                    r instanceof DecodeResult.Decoded d ? d.message() : null);
        }
    }

    /**
     * A bridged robot's channel Touchline recorded in the robot's own encoding and schema
     * ({@code /bridge/ROBOT/TOPIC}, metadata saying whose it is): replayed as the bridge gave it
     * live, a {@link Channel#BRIDGE} envelope of that robot, decoded into {@link Envelope#ros()}
     * (ROS 2 CDR, JSON) or {@link Envelope#message()} (protobuf); one that does not decode is a
     * malformed envelope with the reason, counted against the robot.
     */
    record Bridged(EnvelopeLayout.Key key, String encoding, MessageDecoder ros, Descriptor protobuf)
            implements ChannelReading {

        Envelope envelope(long timeMicros, byte[] data) {
            String why;
            if (ros != null) {
                DecodeResult r = ros.decode(data);
                if (r instanceof DecodeResult.Decoded d) {
                    return new Envelope(timeMicros, Direction.IN, Channel.BRIDGE, key.peer(), key.robotId(), key.kind(),
                            null, data, null, key.origin(), Authenticity.NOT_CHECKED, d.message());
                }
                why = ((DecodeResult.Undecodable) r).reason();
            } else {
                try {
                    return new Envelope(timeMicros, Direction.IN, Channel.BRIDGE, key.peer(), key.robotId(), key.kind(),
                            DynamicMessage.parseFrom(protobuf, data), data, null, key.origin());
                } catch (InvalidProtocolBufferException e) {
                    why = e.getMessage();
                }
            }
            return new Envelope(timeMicros, Direction.IN, Channel.BRIDGE, key.peer(), key.robotId(), key.kind(), null,
                    data, encoding + " on " + key.kind() + " does not decode: " + why, key.origin());
        }
    }

    /**
     * Decides for {@code channel}. {@code schema} is its schema (null when it has none);
     * {@code types} finds a protobuf message type by full name among the schemas that parsed.
     */
    /** A bridged channel in its own encoding: decoded as live, or skipped with the reason (its schema missing or unparsable). */
    private static ChannelReading bridged(EnvelopeLayout.Key key, McapReader.ChannelInfo channel, McapReader.Schema schema,
                                          String encoding, Function<String, Descriptor> types) {
        if (channel.messageEncoding().equals("protobuf")) {
            Descriptor type = schema == null ? null : types.apply(schema.name());
            return type == null ? new Skipped(channel.topic(), encoding, "its schema does not define "
                    + (schema == null ? "a type" : schema.name()) + " (or does not parse)")
                    : new Bridged(key, encoding, null, type);
        }
        ChannelDecoding d = new ChannelDecoders().decoding(key.kind(), channel.messageEncoding(),
                schema == null ? "" : schema.name(), schema == null ? "" : schema.encoding(),
                schema == null ? new byte[0] : schema.data());
        return d instanceof ChannelDecoding.Ready r ? new Bridged(key, encoding, r.decoder(), null)
                : new Skipped(channel.topic(), encoding, ((ChannelDecoding.Unsupported) d).reason());
    }

    static ChannelReading of(McapReader.ChannelInfo channel, McapReader.Schema schema,
                             Function<String, Descriptor> types, MessageCodec codec) {
        Map<String, String> m = channel.metadata();
        boolean ownChannel = m.keySet().stream().anyMatch(k -> k.startsWith("touchline."));
        String encoding = (schema == null ? "no schema" : schema.encoding().isEmpty() ? "empty schema"
                : schema.encoding()) + "/" + (channel.messageEncoding().isEmpty() ? "no encoding"
                : channel.messageEncoding());
        if (ownChannel) {
            try {
                EnvelopeLayout.Key key = EnvelopeLayout.Key.fromMetadata(m);
                return key.channel() == Channel.BRIDGE && !channel.messageEncoding().equals(key.encoding())
                        ? bridged(key, channel, schema, encoding, types) : new Touchline(key);
            } catch (RuntimeException e) {
                return new Skipped(channel.topic(), encoding, "not a complete Touchline channel: " + e.getMessage());
            }
        }
        String messageEncoding = channel.messageEncoding();
        if (!messageEncoding.equals("protobuf")) {
            ChannelDecoding d = new ChannelDecoders().decoding(channel.topic(), messageEncoding,
                    schema == null ? "" : schema.name(), schema == null ? "" : schema.encoding(),
                    schema == null ? new byte[0] : schema.data());
            return d instanceof ChannelDecoding.Ready r ? new Decoded(channel.topic(), r.decoder())
                    : new Skipped(channel.topic(), encoding, ((ChannelDecoding.Unsupported) d).reason());
        }
        if (schema == null || !schema.encoding().equals("protobuf")) {
            return new Skipped(channel.topic(), encoding, "protobuf without a protobuf schema");
        }
        Descriptor type = types.apply(schema.name());
        if (type == null) {
            return new Skipped(channel.topic(), encoding, "its schema does not define " + schema.name()
                    + " (or does not parse)");
        }
        if (type.getFullName().equals(touchline.proto.Fumanoid.Message.getDescriptor().getFullName())) {
            return new Foreign(channel.topic(), data -> codec.decode(data) instanceof MessageResult.Decoded d
                    ? d.message() : null);
        }
        return new Foreign(channel.topic(), data -> {
            try {
                return DynamicMessage.parseFrom(type, data);
            } catch (InvalidProtocolBufferException e) {
                return null;
            }
        });
    }
}
