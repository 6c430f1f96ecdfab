package touchline.model;

import touchline.proto.Fumanoid;
import touchline.protocol.MatchDigestParts;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.List;

/**
 * Between the Envelope stream and what shows robots' data (robots, options, view stores): a
 * robot's match digest is passed on as it came, then each message in it as its own envelope,
 * marked as a {@linkplain Envelope#matchPart() match part}, at the digest's time and origin.
 * So a plot, the field or the text log moves once per digest, as if the robot had streamed.
 * What counts traffic, measures the rule or records subscribes beside this and sees the
 * datagram only.
 */
public final class MatchDigestUnpacker implements EnvelopeSink {

    private final MatchDigestParts parts;
    private final List<EnvelopeSink> next;

    public MatchDigestUnpacker(MatchDigestParts parts, List<EnvelopeSink> next) {
        this.parts = parts;
        this.next = List.copyOf(next);
    }

    @Override
    public void accept(Envelope e) {
        for (EnvelopeSink sink : next) {
            sink.accept(e);
        }
        if (e.matchPart() || !(e.message() instanceof Fumanoid.Message m) || !e.kind().equals("matchDigest")) {
            return;
        }
        for (MatchDigestParts.Part p : parts.of(m)) {
            Envelope part = new Envelope(e.timeMicros(), e.direction(), e.channel(), e.peer(), e.robotId(), p.kind(),
                    p.message(), p.bytes(), null, e.origin(), e.authenticity(), true);
            for (EnvelopeSink sink : next) {
                sink.accept(part);
            }
        }
    }
}
