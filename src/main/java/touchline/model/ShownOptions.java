package touchline.model;

import touchline.proto.Fumanoid;
import touchline.protocol.DebugData;
import touchline.protocol.MessageKinds;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The robots' option lists and when each option's data last came, as a stream carries them,
 * only to show them: the replay stream's read model of the options (subscribed there by the
 * console), beside {@link DebugOptionSession}, which switches the live robots' options and
 * subscribes to the live stream. Nothing here can send: it has no way to.
 */
public final class ShownOptions implements EnvelopeSink {

    private final DebugData debugData;
    private final MicrosClock clock;
    private final Utf8Names names = new Utf8Names();
    private final Map<Integer, Shown> robots = new HashMap<>();
    private long version;

    private static final class Shown {
        boolean listReceived;
        final Map<String, Fumanoid.DebugOption> list = new LinkedHashMap<>();
        final Map<String, long[]> lastData = new HashMap<>();
    }

    /** @param clock the stream's "now" (a replay's position): an option streams by it */
    public ShownOptions(MessageKinds kinds, MicrosClock clock) {
        this.debugData = new DebugData(kinds);
        this.clock = clock;
    }

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN || e.robotId() < 0 || !(e.message() instanceof Fumanoid.Message m)) {
            return;
        }
        Fumanoid.DebugOptionList list = e.extension(Fumanoid.debugOptionList);
        com.google.protobuf.Message data = list == null ? debugData.dataOf(e.kind(), m) : null;
        String option = data == null ? null : names.optionOf(data);
        synchronized (this) {
            Shown r = robots.computeIfAbsent(e.robotId(), k -> new Shown());
            if (list != null) {
                r.list.clear();
                list.getOptionsList().forEach(o -> r.list.put(o.getName(), o));
                r.listReceived = true;
                version++;
            } else if (option != null) {
                r.lastData.computeIfAbsent(option, k -> new long[1])[0] = e.timeMicros();
            }
        }
    }

    /** Forgets every robot's options (the replay closed). */
    public synchronized void forget() {
        robots.clear();
        version++;
    }

    /** A robot's options as shown: none wanted, none switchable. */
    public synchronized RobotOptions options(int robotId) {
        Shown r = robots.get(robotId);
        if (r == null) {
            return new RobotOptions(robotId, false, 0, List.of(), "");
        }
        long now = clock.nowMicros();
        List<OptionState> states = new ArrayList<>();
        for (Fumanoid.DebugOption o : r.list.values()) {
            long[] last = r.lastData.get(o.getName());
            states.add(new OptionState(o.getName(), o.getDescription(), o.getKind(), false, o.getEnabled(),
                    last != null && now - last[0] <= DebugOptionSession.STREAMING_WINDOW_MICROS,
                    o.getMatchRank(), o.getMatchRank())); // the recorded robot's match place, as it had it
        }
        return new RobotOptions(robotId, r.listReceived, 0, states, "");
    }

    public synchronized long version() {
        return version;
    }
}
