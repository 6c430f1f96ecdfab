package touchline.model.store;

import touchline.proto.Fumanoid;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.List;

/**
 * The debug console's memory: every {@code DebugText} line, time-stamped on receipt, in one
 * capped ring so a chatty robot costs bounded memory. Views filter by robot when they read.
 */
public final class TextLog implements EnvelopeSink {

    public static final int DEFAULT_CAPACITY = 20_000;
    private final SequencedRing<TextLine> lines;
    private final touchline.model.Utf8Names names = new touchline.model.Utf8Names();

    public TextLog(int capacity) {
        this.lines = new SequencedRing<>(capacity);
    }

    @Override
    public void accept(Envelope e) {
        add(e, e.direction() == Direction.IN ? e.extension(Fumanoid.debugText) : null);
    }

    /** Keeps an inbound envelope's text; {@code t} found by the caller, null when it carries none. */
    void add(Envelope e, Fumanoid.DebugText t) {
        if (t != null) {
            lines.append(new TextLine(e.timeMicros(), t.getTimestamp(), e.robotId(), names.of(t.getOptionBytes()),
                    t.getText()));
        }
    }

    /** Keeps a ROS 2 robot's log line: the node as the option, the level before the text. */
    void add(Envelope e, touchline.model.RosReadings.LogLine l) {
        lines.append(new TextLine(e.timeMicros(), 0, e.robotId(), l.node(), "[" + l.level() + "] " + l.text()));
    }

    /** Lines after {@code afterSeq} from one robot (or all when {@code robotId < 0}), at most {@code max}. */
    public List<SequencedRing.Entry<TextLine>> since(long afterSeq, int robotId, int max) {
        return lines.since(afterSeq, max, l -> robotId < 0 || l.robotId() == robotId);
    }

    public long version() {
        return lines.version();
    }

    public int capacity() {
        return lines.capacity();
    }

    public int size() {
        return lines.size();
    }

    /** Drops what is kept; sequence numbers go on (views following the log see only what comes next). */
    public void forget() {
        lines.forget();
    }
}
