package touchline.transport;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.ChannelInboundHandlerAdapter;
import touchline.protocol.DatagramClass;
import touchline.protocol.FrameCodec;
import touchline.protocol.FrameResult;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageResult;
import touchline.security.Authenticity;
import touchline.security.InboundVerifier;
import touchline.security.MessageTag;

import java.util.function.Supplier;

/**
 * Turns classified datagrams into Envelopes: FUmanoids frames are decoded (or become a
 * malformed Envelope with the reason), GameController packets pass as raw GC Envelopes, and
 * the robot's address and framing are learned for the way back. The end of the UDP
 * pipeline: each Envelope goes straight to the stream (no further hop per datagram).
 */
final class FumanoidDecoder extends ChannelInboundHandlerAdapter {

    private final FrameCodec frames;
    private final MessageCodec messages;
    private final PeerTable peers;
    private final TrafficCounters counters;
    private final EnvelopeSink sink;
    private final InboundVerifier verifier;
    /**
     * Where datagrams are decoded and published, beside this thread (which receives and, with a
     * team key, takes the frame apart and shares the HMACs); with a key their tags and counters
     * are checked there, in order. Null: everything on this thread.
     */
    private final DecodeStage stage;

    /** @param stage null: everything on the event loop; else decode and publish there (and check the tags there with a key) */
    FumanoidDecoder(FrameCodec frames, MessageCodec messages, PeerTable peers, TrafficCounters counters,
                    EnvelopeSink sink, InboundVerifier verifier, DecodeStage stage) {
        this.verifier = verifier;
        this.stage = stage;
        this.frames = frames;
        this.messages = messages;
        this.peers = peers;
        this.counters = counters;
        this.sink = sink;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (!(msg instanceof ReceivedDatagram d)) {
            ctx.fireChannelRead(msg);
        } else if (stage == null) {
            sink.accept(toEnvelope(d));
        } else if (!verifier.hasKey()) {
            stage.add(() -> toEnvelope(d)); // decoded and published on the stage, beside the next read
        } else {
            stage.add(checked(d));
        }
    }

    @Override
    public void channelReadComplete(ChannelHandlerContext ctx) {
        if (stage != null) {
            stage.flush();
        }
        ctx.fireChannelReadComplete();
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        // A decoder or sink failure must not close the channel; this datagram is lost, the next one is not.
        org.slf4j.LoggerFactory.getLogger(FumanoidDecoder.class).warn("inbound pipeline: {}", cause.toString());
    }

    Envelope toEnvelope(ReceivedDatagram d) {
        if (d.datagramClass() == DatagramClass.GAMECONTROLLER) {
            return gameController(d);
        }
        byte[] bytes = d.bytes();
        FrameResult frame = frames.decode(bytes, InboundVerifier.payloadLength(bytes));
        if (frame instanceof FrameResult.Malformed m) {
            return malformed(d, m.reason());
        }
        FrameResult.Frame f = (FrameResult.Frame) frame;
        MessageResult result = messages.decode(f.payload());
        if (result instanceof MessageResult.Malformed m) {
            return malformed(d, m.reason());
        }
        MessageResult.Decoded decoded = (MessageResult.Decoded) result;
        int robotId = decoded.message().getRobotID();
        InboundVerifier.Result auth = verifier.check(robotId, bytes);
        if (auth.authenticity() == Authenticity.FORGED) {
            return forged(d, robotId, auth);
        }
        accepted(d, robotId, f, auth);
        return envelope(d, robotId, decoded, auth);
    }

    /**
     * With a team key, on the event loop: the frame is taken apart here; the message is decoded
     * and its tag and counter checked on the {@link DecodeStage} (the returned work), in arrival
     * order with the reliable stream's segments, which share the robot's counter and are checked
     * there too. While the stage is the slower thread ({@link DecodeStage#behind}) the event loop
     * computes the HMAC itself (it needs no order; the robot ID read from the bytes) and the stage
     * only settles the counter. So the two threads share the work by how busy they are. A
     * forgery may thus be decoded before it is refused, but what it says is never published: its
     * envelope carries no message, its robot's address is not learned, and it is counted and
     * shown with its source.
     */
    private Supplier<Envelope> checked(ReceivedDatagram d) {
        if (d.datagramClass() == DatagramClass.GAMECONTROLLER) {
            Envelope gc = gameController(d);
            return () -> gc;
        }
        byte[] bytes = d.bytes();
        FrameResult frame = frames.decode(bytes, InboundVerifier.payloadLength(bytes));
        if (frame instanceof FrameResult.Malformed m) {
            Envelope bad = malformed(d, m.reason());
            return () -> bad;
        }
        FrameResult.Frame f = (FrameResult.Frame) frame;
        if (!stage.behind()) {
            return () -> decodedAndChecked(d, f, MessageCodec.NO_ROBOT_ID, null);
        }
        int prechecked = MessageCodec.robotIdOf(f.payload());
        MessageTag.Check tag = prechecked == MessageCodec.NO_ROBOT_ID ? null : verifier.precheck(prechecked, bytes);
        return () -> decodedAndChecked(d, f, prechecked, tag);
    }

    /** On the stage: the message decoded, then its {@link #verdict}; {@code tag} holds for robot {@code prechecked} only. */
    private Envelope decodedAndChecked(ReceivedDatagram d, FrameResult.Frame f, int prechecked, MessageTag.Check tag) {
        MessageResult result = messages.decode(f.payload());
        int robotId = result instanceof MessageResult.Decoded decoded
                ? decoded.message().getRobotID() : MessageCodec.robotIdOf(f.payload());
        if (robotId == MessageCodec.NO_ROBOT_ID) {
            // nothing to check a tag against: the decoder says why (no robotID, not protobuf)
            return malformed(d, ((MessageResult.Malformed) result).reason());
        }
        return verdict(d, robotId, f, result, robotId == prechecked ? tag : null);
    }

    /**
     * On the stage, in arrival order: the tag and the counter decide whether the decoded message
     * is published; a forged one is replaced by its forged envelope (no message), counted.
     */
    private Envelope verdict(ReceivedDatagram d, int robotId, FrameResult.Frame f, MessageResult result,
                             MessageTag.Check tag) {
        InboundVerifier.Result auth = verifier.check(robotId, d.bytes(), tag);
        if (auth.authenticity() == Authenticity.FORGED) {
            return forged(d, robotId, auth);
        }
        accepted(d, robotId, f, auth);
        return result instanceof MessageResult.Decoded decoded
                ? envelope(d, robotId, decoded, auth) : malformed(d, ((MessageResult.Malformed) result).reason());
    }

    private Envelope gameController(ReceivedDatagram d) {
        return new Envelope(d.timeMicros(), Direction.IN, Channel.GAMECONTROLLER, d.sender(), Envelope.NO_ROBOT,
                "gc", null, d.bytes(), null);
    }

    /** A forged datagram: neither the robot's address nor its data is taken; counted and shown with its source. */
    private Envelope forged(ReceivedDatagram d, int robotId, InboundVerifier.Result auth) {
        counters.countForged();
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), robotId, "forged", null,
                d.bytes(), auth.reason() + " (claims robot " + robotId + ")", Origin.LIVE, Authenticity.FORGED);
    }

    /**
     * A datagram that passed the check: counted, and its robot's address learned for the way
     * back, except an untagged robot's while the console has a key: it is shown, never commanded.
     */
    private void accepted(ReceivedDatagram d, int robotId, FrameResult.Frame f, InboundVerifier.Result auth) {
        if (auth.authenticity() == Authenticity.UNVERIFIED || auth.authenticity() == Authenticity.UNTAGGED) {
            counters.countUnverified();
        }
        if (auth.note() != null) {
            org.slf4j.LoggerFactory.getLogger(FumanoidDecoder.class).info(auth.note());
        }
        if (robotId >= 0 && auth.authenticity() == Authenticity.UNTAGGED) {
            peers.untagged(robotId);
        } else if (robotId >= 0) {
            peers.learn(robotId, d.sender(), f.framing());
        }
    }

    private static Envelope envelope(ReceivedDatagram d, int robotId, MessageResult.Decoded decoded,
                                     InboundVerifier.Result auth) {
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), robotId, decoded.kind(),
                decoded.message(), d.bytes(), null, Origin.LIVE, auth.authenticity());
    }

    private Envelope malformed(ReceivedDatagram d, String reason) {
        counters.countMalformed();
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), Envelope.NO_ROBOT,
                "malformed", null, d.bytes(), reason);
    }

}
