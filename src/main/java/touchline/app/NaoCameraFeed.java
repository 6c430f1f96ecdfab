package touchline.app;

import com.google.protobuf.InvalidProtocolBufferException;
import touchline.proto.Nao.CamResponse;
import touchline.protocol.nao.JpegHeader;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.util.Optional;
import java.util.function.BooleanSupplier;

/**
 * The NAO cameras' newest frame, taken from the console's Envelope stream ({@link
 * Channel#NAO_CAMERA}, the frames a camera stream publishes) rather than from a camera stream:
 * so it holds frames fetched here, frames a remote Touchline sent as envelopes, and replayed
 * ones alike. One slot per stream, as the view stores have: {@link #live()} subscribed to the
 * live stream, {@link #replay()} to the replay stream, whose frames are shown while a replay is open. Written by whichever thread publishes, read by the faces at their own
 * rate; it keeps one frame and the receive figures of the last {@value #WINDOW}.
 */
public final class NaoCameraFeed {

    static final int WINDOW = 30;
    /** A rate whose newest frame is older than this is no rate any more: 0 fps. */
    static final long STALE_MICROS = 2_000_000;

    /** One numbering for both origins, so a view redraws when it turns from live frames to replayed ones. */
    private final java.util.concurrent.atomic.AtomicLong sequence = new java.util.concurrent.atomic.AtomicLong();
    private final Slot live;
    private final Slot replayed;
    private final BooleanSupplier replaying;

    /**
     * @param clock       the live "now" (the frame rate's staleness)
     * @param replayClock the replay's position
     * @param replaying   whether a replay is open (its frames are shown then)
     */
    NaoCameraFeed(MicrosClock clock, MicrosClock replayClock, BooleanSupplier replaying) {
        this.live = new Slot(clock, sequence);
        this.replayed = new Slot(replayClock, sequence);
        this.replaying = replaying;
    }

    /** The live stream's frames: subscribe this to the live stream. */
    EnvelopeSink live() {
        return live;
    }

    /** The replay's frames: subscribe this to the replay stream. */
    EnvelopeSink replay() {
        return replayed;
    }

    /** The newest frame shown (the replay's while one is open), if any arrived. */
    public Optional<NaoFrame> latest() {
        return Optional.ofNullable(shown().frame());
    }

    /** Frames per second over the last up to {@value #WINDOW} frames; 0 with fewer than two, or none for 2 s. */
    public double framesPerSecond() {
        return shown().framesPerSecond();
    }

    /** Mean JPEG size over the last up to {@value #WINDOW} frames, 0 before the first. */
    public double bytesPerFrame() {
        return shown().bytesPerFrame();
    }

    /** What the last camera reply said was wrong (the server's error, an unreadable reply); "" once frames flow. */
    public String problem() {
        return shown().problem();
    }

    /** A replay opened, jumped or closed: its frames start afresh. */
    void restartReplay() {
        replayed.clear();
    }

    private Slot shown() {
        return replaying.getAsBoolean() ? replayed : live;
    }

    /** The frames of one stream (live or replayed). */
    private static final class Slot implements EnvelopeSink {
        private final MicrosClock clock;
        private final java.util.concurrent.atomic.AtomicLong sequence;
        private final long[] arrivals = new long[WINDOW];
        private final int[] sizes = new int[WINDOW];
        private int count;
        private volatile NaoFrame frame;
        private String problem = "";

        Slot(MicrosClock clock, java.util.concurrent.atomic.AtomicLong sequence) {
            this.clock = clock;
            this.sequence = sequence;
        }

        @Override
        public void accept(Envelope e) {
            if (e.channel() == Channel.NAO_CAMERA && e.direction() == Direction.IN) {
                take(e);
            }
        }

        private void take(Envelope e) {
            if (e.kind().equals("malformed") || e.error() != null) {
                said("unreadable camera reply" + (e.error() == null ? "" : ": " + e.error()));
                return;
            }
            CamResponse response;
            try {
                response = e.raw() == null ? null : CamResponse.parseFrom(e.raw());
            } catch (InvalidProtocolBufferException bad) {
                said("unreadable camera reply: " + bad.getMessage());
                return;
            }
            if (response == null) {
                return;
            }
            if (response.hasError()) {
                said("camera server: " + response.getError());
            } else if (e.kind().equals("frame") && response.hasImageData()) {
                frame(e, response.getImageData().toByteArray());
            }
        }

        private synchronized void frame(Envelope e, byte[] jpeg) {
            int[] size = JpegHeader.size(jpeg);
            arrivals[count % WINDOW] = clock.nowMicros();
            sizes[count % WINDOW] = jpeg.length;
            count++;
            problem = "";
            frame = new NaoFrame(jpeg, size == null ? 0 : size[0], size == null ? 0 : size[1], sequence.incrementAndGet(),
                    e.timeMicros(), e.peer() == null ? "" : e.peer().getHostString() + ":" + e.peer().getPort());
        }

        private synchronized void said(String why) {
            problem = why;
        }

        NaoFrame frame() {
            return frame;
        }

        synchronized String problem() {
            return problem;
        }

        synchronized double framesPerSecond() {
            int n = Math.min(count, WINDOW);
            if (n < 2) {
                return 0;
            }
            long newest = arrivals[(count - 1) % WINDOW];
            long oldest = arrivals[(count - n) % WINDOW];
            if (clock.nowMicros() - newest > STALE_MICROS || newest == oldest) {
                return 0;
            }
            return (n - 1) * 1e6 / (newest - oldest);
        }

        synchronized double bytesPerFrame() {
            int n = Math.min(count, WINDOW);
            long sum = 0;
            for (int i = 0; i < n; i++) {
                sum += sizes[i];
            }
            return n == 0 ? 0 : (double) sum / n;
        }

        synchronized void clear() {
            count = 0;
            problem = "";
            frame = null;
        }
    }
}
