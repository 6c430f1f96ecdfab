package touchline.transport.remote;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.DynamicMessage;
import com.google.protobuf.InvalidProtocolBufferException;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.MessageDecoder;
import touchline.security.Authenticity;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;
import touchline.transport.Origin;

import java.net.InetSocketAddress;

/**
 * One channel of a robot's Foxglove bridge: each payload becomes an envelope of the bridge's
 * robot ({@link Channel#BRIDGE}, kind = the topic, raw = the payload as sent), time-stamped on
 * this console's clock (a robot's own clock may be anything), decoded: a ROS 2 or JSON message
 * into {@link Envelope#ros()}, a protobuf one into {@link Envelope#message()}. A payload that
 * does not decode becomes an envelope with the reason as its error: counted against the robot
 * and shown, never dropped unseen.
 */
final class BridgedChannel implements StreamChannel {

    private final int id;
    private final String topic;
    private final String encoding;
    private final MessageDecoder ros;   // null: a protobuf channel
    private final Descriptor protobuf;  // null: a ROS 2 or JSON channel
    private final int robotId;
    private final InetSocketAddress peer;
    private final MicrosClock clock;
    private final java.util.concurrent.atomic.AtomicLong undecodable = new java.util.concurrent.atomic.AtomicLong();

    /** A ROS 2 (CDR) or JSON channel, decoded by {@code ros}. */
    BridgedChannel(int id, String topic, String encoding, MessageDecoder ros, int robotId, InetSocketAddress peer,
                   MicrosClock clock) {
        this(id, topic, encoding, ros, null, robotId, peer, clock);
    }

    /** A protobuf channel of type {@code protobuf}. */
    BridgedChannel(int id, String topic, Descriptor protobuf, int robotId, InetSocketAddress peer, MicrosClock clock) {
        this(id, topic, "protobuf", null, protobuf, robotId, peer, clock);
    }

    private BridgedChannel(int id, String topic, String encoding, MessageDecoder ros, Descriptor protobuf, int robotId,
                           InetSocketAddress peer, MicrosClock clock) {
        this.id = id;
        this.topic = topic;
        this.encoding = encoding;
        this.ros = ros;
        this.protobuf = protobuf;
        this.robotId = robotId;
        this.peer = peer;
        this.clock = clock;
    }

    @Override
    public int id() {
        return id;
    }

    @Override
    public String topic() {
        return topic;
    }

    @Override
    public Envelope rebuild(byte[] payload, long timeNanos) {
        long now = clock.nowMicros();
        if (ros != null) {
            DecodeResult r = ros.decode(payload);
            return r instanceof DecodeResult.Decoded d
                    ? new Envelope(now, Direction.IN, Channel.BRIDGE, peer, robotId, topic, null, payload, null,
                            Origin.LIVE, Authenticity.NOT_CHECKED, d.message())
                    : undecodable(now, payload, ((DecodeResult.Undecodable) r).reason());
        }
        try {
            return new Envelope(now, Direction.IN, Channel.BRIDGE, peer, robotId, topic,
                    DynamicMessage.parseFrom(protobuf, payload), payload, null, Origin.LIVE);
        } catch (InvalidProtocolBufferException e) {
            return undecodable(now, payload, e.getMessage());
        }
    }

    /** Messages on this channel that did not decode. */
    long undecodable() {
        return undecodable.get();
    }

    private Envelope undecodable(long now, byte[] payload, String why) {
        undecodable.incrementAndGet();
        return new Envelope(now, Direction.IN, Channel.BRIDGE, peer, robotId, topic, null, payload,
                encoding + " on " + topic + " does not decode: " + why, Origin.LIVE);
    }
}
