package touchline.app;

import com.google.protobuf.InvalidProtocolBufferException;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.nao.CallOutcome;

import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;

/**
 * The newest NAO call and its outcome in words, taken from the console's Envelope stream
 * ({@link Channel#NAO_RPC}: a call going out, the NAO's reply coming in) rather than from a
 * NAO link, as {@link NaoCameraFeed} takes the frames: so a console viewing a remote Touchline,
 * or replaying a recording, can say what the NAO there was asked and answered. A call whose
 * reply never came (timed out, lost on the first console) stays "sent, no reply yet": no
 * envelope tells its end. One slot per stream: {@link #live()} subscribed to the live stream,
 * {@link #replay()} to the replay stream, whose calls are shown while a replay is open.
 * Written by whichever thread publishes, read by the faces at their own rate.
 */
public final class NaoCallFeed {

    public static final String NO_REPLY_YET = "sent, no reply yet";

    /** One numbering for both origins, so a reader sees a change when a replay opens or closes. */
    private final AtomicLong sequence = new AtomicLong();
    /** Reads a response as the NAO link does: the robot's error, "done", or the value. */
    private final touchline.transport.nao.ReplyReader replies = new touchline.transport.nao.ReplyReader();
    private final Slot live = new Slot();
    private final Slot replayed = new Slot();
    private final BooleanSupplier replaying;

    /** @param replaying whether a replay is open (its calls are shown then) */
    NaoCallFeed(BooleanSupplier replaying) {
        this.replaying = replaying;
    }

    /** The live stream's calls: subscribe this to the live stream. */
    EnvelopeSink live() {
        return live;
    }

    /** The replay's calls: subscribe this to the replay stream. */
    EnvelopeSink replay() {
        return replayed;
    }

    /** The newest call and its outcome ("ALTextToSpeech.getVolume: 80"), "" before the first call. */
    public String line() {
        return shown().line;
    }

    /** Grows with every new {@link #line()} (of either origin); 0 before the first. */
    public long version() {
        return shown().version;
    }

    /** Whether the replay's calls are shown (a replay is open); never blocks. */
    public boolean showsReplay() {
        return replaying.getAsBoolean();
    }

    /** A replay opened, jumped or closed: its calls start afresh. */
    void restartReplay() {
        replayed.say("", sequence.incrementAndGet());
    }

    private Slot shown() {
        return replaying.getAsBoolean() ? replayed : live;
    }

    /** A reply in words: the call's name (the link names a reply by its call) and its outcome. */
    private String reply(Envelope e) {
        if (e.kind().equals("malformed") || e.error() != null) {
            return "unreadable NAO reply" + (e.error() == null ? "" : ": " + e.error());
        }
        String call = e.kind().equals("stray") ? "a reply to no waiting call" : e.kind();
        if (e.raw() == null) {
            return call + ": replied (the reply's bytes did not come along)";
        }
        try {
            return call + ": " + replies.outcomeOf(HAWActorRPCResponse.parseFrom(e.raw())).describe();
        } catch (InvalidProtocolBufferException bad) {
            return call + ": unreadable reply: " + bad.getMessage();
        }
    }

    /** The newest line of one stream (live or replayed). */
    private final class Slot implements EnvelopeSink {
        private volatile String line = "";
        private volatile long version;

        @Override
        public void accept(Envelope e) {
            if (e.channel() != Channel.NAO_RPC) {
                return;
            }
            if (e.direction() == Direction.OUT) {
                say(e.kind() + ": " + NO_REPLY_YET, sequence.incrementAndGet());
            } else if (e.direction() == Direction.IN) {
                say(reply(e), sequence.incrementAndGet());
            }
        }

        synchronized void say(String what, long at) {
            line = what;
            version = at;
        }
    }
}
