package touchline.model.store;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.DebugData;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The newest value of every robot's debug option (tables, regions, grids, positions, field
 * objects, images, text, plots): views showing "the current picture" read only this, so
 * memory is one message per robot and option however fast the robot sends. Plot history
 * lives in {@link PlotStore}, text history in {@link TextLog}.
 */
public final class LatestValues implements EnvelopeSink {

    /** Key of one robot's option. */
    public record Key(int robotId, String option) { }

    private final Map<Key, Latest> latest = new ConcurrentHashMap<>();
    private final AtomicLong version = new AtomicLong();
    private final Map<Key, Integer> translatedKinds = new ConcurrentHashMap<>();
    private final touchline.model.RosDebugData rosData = new touchline.model.RosDebugData();
    private final touchline.model.Utf8Names names = new touchline.model.Utf8Names();
    /**
     * ROS 2 joint states and diagnostics as they came, the newest per robot and topic, made into
     * their tables only when a view reads them: eight robots' joints at 30 Hz each, 72 numbers
     * formatted per message, took a third of what the window allocated, for tables mostly in tabs
     * nobody looked at (docs/archive/benchmarks-sessions.md, "Window CPU with eight bridges").
     */
    private final Map<Key, Untranslated> untranslated = new ConcurrentHashMap<>();
    private final java.util.function.BiFunction<String, touchline.protocol.ros2.RosMessage,
            Optional<Fumanoid.DebugTable>> tables;

    /** A ROS 2 message kept for its table, with the version it took when it came. */
    private record Untranslated(Envelope envelope, long version) { }

    public LatestValues() {
        this(new touchline.model.RosTables()::table);
    }

    /** @param tables what makes a ROS 2 message its table (the tests count how often it is asked) */
    LatestValues(java.util.function.BiFunction<String, touchline.protocol.ros2.RosMessage,
            Optional<Fumanoid.DebugTable>> tables) {
        this.tables = tables;
    }

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN || e.robotId() < 0 || !(e.message() instanceof Fumanoid.Message m)) {
            return;
        }
        accept(e, m, DebugData.ownDataOf(e.kind(), m));
    }

    /**
     * Keeps an inbound robot's envelope's value: {@code own} is its data of one of our own kinds,
     * found by the caller ({@link DebugData#ownDataOf}), null for none or a team's own type.
     */
    void accept(Envelope e, Fumanoid.Message m, Message own) {
        if (own != null) {
            keep(e, own);
            return;
        }
        if (DebugData.isOwnKind(e.kind())) {
            return; // status, option lists and requests: not debug data
        }
        // a team's own type: found through reflection (rare, so its cost does not matter)
        for (Map.Entry<FieldDescriptor, Object> f : m.getAllFields().entrySet()) {
            if (f.getKey().isExtension() && f.getValue() instanceof Message data) {
                keep(e, data);
            }
        }
    }

    private void keep(Envelope e, Message data) {
        String option = names.optionOf(data);
        if (option != null) {
            latest.put(new Key(e.robotId(), option),
                    new Latest(e.robotId(), option, e.kind(), data, e.timeMicros(), version.incrementAndGet()));
        }
    }

    /**
     * Keeps a ROS 2 robot's inbound message as the data a view shows ({@link touchline.model.RosDebugData}:
     * images, tables, markers), if it is one of those types.
     */
    synchronized void acceptRos(Envelope e) {
        if (e.robotId() < 0 || e.ros() == null) {
            return;
        }
        if (touchline.model.RosTables.isTable(e.ros().typeName())) {
            Key key = new Key(e.robotId(), e.kind());
            untranslated.put(key, new Untranslated(e, version.incrementAndGet()));
            translatedKinds.put(key, Fumanoid.DebugKind.TABLE_VALUE);
            return;
        }
        rosData.of(e.robotId(), e.kind(), e.ros()).ifPresent(d -> keepTranslated(e, d.data(), d.debugKind()));
    }

    /** Makes {@code u} its table for the readers; a newer value kept meanwhile stays. */
    private void translate(Key key, Untranslated u) {
        Envelope e = u.envelope();
        Optional<Fumanoid.DebugTable> table = tables.apply(e.kind(), e.ros());
        if (untranslated.remove(key, u) && table.isPresent()) {
            Latest l = new Latest(e.robotId(), key.option(), e.kind(), table.get(), e.timeMicros(), u.version());
            latest.merge(key, l, (was, now) -> was.version() > now.version() ? was : now);
        }
    }

    /**
     * Keeps a ROS 2 robot's message translated to debug data ({@link touchline.model.RosDebugData}):
     * its topic is the option, and views find it as a source by {@code debugKind}.
     */
    void keepTranslated(Envelope e, Message data, int debugKind) {
        keep(e, data);
        String option = names.optionOf(data);
        if (option != null) {
            translatedKinds.put(new Key(e.robotId(), option), debugKind);
        }
    }

    /** The robots' ROS 2 topics kept as data a view of one of {@code debugKinds} shows. */
    public List<Key> translatedSources(java.util.Set<Integer> debugKinds) {
        List<Key> out = new ArrayList<>();
        translatedKinds.forEach((k, kind) -> {
            if (debugKinds.contains(kind)) {
                out.add(k);
            }
        });
        out.sort(java.util.Comparator.comparingInt(Key::robotId).thenComparing(Key::option));
        return out;
    }

    public Optional<Latest> get(int robotId, String option) {
        Key key = new Key(robotId, option);
        Untranslated u = untranslated.get(key);
        if (u != null) {
            translate(key, u);
        }
        return Optional.ofNullable(latest.get(key));
    }

    /** Every robot's newest value of messages of one kind (e.g. {@code fieldObjects}). */
    public List<Latest> ofKind(String kind) {
        untranslated.forEach((key, u) -> {
            if (u.envelope().kind().equals(kind)) {
                translate(key, u);
            }
        });
        List<Latest> out = new ArrayList<>();
        for (Latest l : latest.values()) {
            if (l.kind().equals(kind)) {
                out.add(l);
            }
        }
        return out;
    }

    public long version() {
        return version.get();
    }

    /** Drops every value; the version goes on counting, so a view notices the next value. */
    public void clear() {
        latest.clear();
        untranslated.clear();
        translatedKinds.clear();
        synchronized (this) {
            rosData.forget();
        }
        version.incrementAndGet();
    }
}
