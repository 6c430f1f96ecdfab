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
                EnvelopeLayout.layoutOf(e), null, e.origin()).topic();
    }

    /**
     * The facts the recording keeps in its channel's metadata ({@code touchline.direction},
     * {@code .channel}, {@code .peer}, {@code .robot}, {@code .kind}, {@code .layout},
     * {@code .framing}, {@code .origin}): what another Touchline needs to rebuild {@code e} from its payload.
     */
    public java.util.Map<String, String> metadata(Envelope e) {
        String layout = EnvelopeLayout.layoutOf(e);
        return new EnvelopeLayout.Key(e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(), layout,
                layout.equals(EnvelopeLayout.PAYLOAD) ? EnvelopeLayout.exactFraming(e.raw()) : null, e.origin()).metadata();
    }
}
