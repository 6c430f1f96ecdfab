package touchline.record;

import touchline.transport.Envelope;

/**
 * The topic an envelope is recorded under (e.g. {@code /robot/3/status}), for anything that
 * names the same streams outside a recording, such as the live server's channels, so a
 * layout made for a recording works on the live stream too.
 */
public final class Topics {

    /** The MCAP topic {@code e} is recorded under. */
    public String of(Envelope e) {
        return new EnvelopeLayout.Key(e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(),
                EnvelopeLayout.layoutOf(e), null).topic();
    }
}
