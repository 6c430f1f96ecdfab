package touchline.record;

import touchline.transport.Envelope;

import java.time.Instant;

/** One Envelope as one line of text for headless replay: time, direction, channel, robot, kind, size, error. */
public final class EnvelopeText {

    public String line(Envelope e) {
        StringBuilder s = new StringBuilder(96);
        s.append(Instant.ofEpochSecond(Math.floorDiv(e.timeMicros(), 1_000_000L), Math.floorMod(e.timeMicros(), 1_000_000L) * 1000L))
                .append(' ').append(e.direction()).append(' ').append(e.channel())
                .append(" robot=").append(e.robotId() == Envelope.NO_ROBOT ? "-" : Integer.toString(e.robotId()))
                .append(' ').append(e.kind()).append(' ').append(e.raw().length).append(" B");
        if (e.error() != null) {
            s.append(" error=").append(e.error());
        }
        return s.toString();
    }
}
