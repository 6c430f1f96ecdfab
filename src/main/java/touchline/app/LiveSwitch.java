package touchline.app;

import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

/**
 * Between the live transports and the Envelope stream: the user may pause live listening while
 * a replay runs (or let both run side by side). Paused envelopes are counted, not queued.
 */
final class LiveSwitch implements EnvelopeSink {

    private final EnvelopeSink next;
    private volatile boolean live = true;
    private final java.util.concurrent.atomic.LongAdder skipped = new java.util.concurrent.atomic.LongAdder();

    LiveSwitch(EnvelopeSink next) {
        this.next = next;
    }

    void setLive(boolean live) {
        this.live = live;
    }

    boolean isLive() {
        return live;
    }

    long skipped() {
        return skipped.sum();
    }

    @Override
    public void accept(Envelope envelope) {
        if (live) {
            next.accept(envelope);
        } else {
            skipped.increment();
        }
    }
}
