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

import java.util.Arrays;

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

    FumanoidDecoder(FrameCodec frames, MessageCodec messages, PeerTable peers, TrafficCounters counters,
                    EnvelopeSink sink, InboundVerifier verifier) {
        this.verifier = verifier;
        this.frames = frames;
        this.messages = messages;
        this.peers = peers;
        this.counters = counters;
        this.sink = sink;
    }

    @Override
    public void channelRead(ChannelHandlerContext ctx, Object msg) {
        if (msg instanceof ReceivedDatagram d) {
            sink.accept(toEnvelope(d));
        } else {
            ctx.fireChannelRead(msg);
        }
    }

    @Override
    public void exceptionCaught(ChannelHandlerContext ctx, Throwable cause) {
        // A decoder or sink failure must not close the channel; this datagram is lost, the next one is not.
        org.slf4j.LoggerFactory.getLogger(FumanoidDecoder.class).warn("inbound pipeline: {}", cause.toString());
    }

    Envelope toEnvelope(ReceivedDatagram d) {
        if (d.datagramClass() == DatagramClass.GAMECONTROLLER) {
            return new Envelope(d.timeMicros(), Direction.IN, Channel.GAMECONTROLLER, d.sender(), Envelope.NO_ROBOT,
                    "gc", null, d.bytes(), null);
        }
        byte[] bytes = d.bytes();
        int payloadLength = InboundVerifier.payloadLength(bytes);
        FrameResult frame = frames.decode(payloadLength == bytes.length ? bytes : Arrays.copyOf(bytes, payloadLength));
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
            // dropped: neither the robot's address nor its data is taken; counted and shown with its source
            counters.countForged();
            return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), robotId, "forged", null,
                    bytes, auth.reason() + " (claims robot " + robotId + ")", Origin.LIVE, Authenticity.FORGED);
        }
        if (auth.authenticity() == Authenticity.UNVERIFIED) {
            counters.countUnverified();
        }
        if (auth.note() != null) {
            org.slf4j.LoggerFactory.getLogger(FumanoidDecoder.class).info(auth.note());
        }
        if (robotId >= 0) {
            peers.learn(robotId, d.sender(), f.framing());
        }
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), robotId, decoded.kind(),
                decoded.message(), bytes, null, Origin.LIVE, auth.authenticity());
    }

    private Envelope malformed(ReceivedDatagram d, String reason) {
        counters.countMalformed();
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), Envelope.NO_ROBOT,
                "malformed", null, d.bytes(), reason);
    }

}
