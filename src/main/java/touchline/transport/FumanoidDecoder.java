package touchline.transport;

import io.netty.channel.ChannelHandlerContext;
import io.netty.handler.codec.MessageToMessageDecoder;
import touchline.protocol.DatagramClass;
import touchline.protocol.FrameCodec;
import touchline.protocol.FrameResult;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageResult;

import java.util.List;

/**
 * Turns classified datagrams into Envelopes: FUmanoids frames are decoded (or become a
 * malformed Envelope with the reason), GameController packets pass as raw GC Envelopes, and
 * the robot's address and framing are learned for the way back.
 */
final class FumanoidDecoder extends MessageToMessageDecoder<ReceivedDatagram> {

    private final FrameCodec frames;
    private final MessageCodec messages;
    private final PeerTable peers;
    private final TrafficCounters counters;

    FumanoidDecoder(FrameCodec frames, MessageCodec messages, PeerTable peers, TrafficCounters counters) {
        this.frames = frames;
        this.messages = messages;
        this.peers = peers;
        this.counters = counters;
    }

    @Override
    protected void decode(ChannelHandlerContext ctx, ReceivedDatagram d, List<Object> out) {
        out.add(toEnvelope(d));
    }

    Envelope toEnvelope(ReceivedDatagram d) {
        if (d.datagramClass() == DatagramClass.GAMECONTROLLER) {
            return new Envelope(d.timeMicros(), Direction.IN, Channel.GAMECONTROLLER, d.sender(), Envelope.NO_ROBOT,
                    "gc", null, d.bytes(), null);
        }
        FrameResult frame = frames.decode(d.bytes());
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
        if (robotId >= 0) {
            peers.learn(robotId, d.sender(), f.framing());
        }
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), robotId, decoded.kind(),
                decoded.message(), d.bytes(), null);
    }

    private Envelope malformed(ReceivedDatagram d, String reason) {
        counters.countMalformed();
        return new Envelope(d.timeMicros(), Direction.IN, Channel.FUMANOID, d.sender(), Envelope.NO_ROBOT,
                "malformed", null, d.bytes(), reason);
    }

}
