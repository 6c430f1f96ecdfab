package touchline.model.store;

import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageKinds;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * "Plot anything": any numeric field of any message kind the robots send (the teams' own
 * types loaded at run time included), per robot, as bounded series — like PlotJuggler. It
 * learns which kinds arrive and offers their numeric field paths ({@code kind:path}); each
 * series the user adds (robot × field path) keeps its last points in a ring. ROS 2 and JSON
 * messages ({@link Envelope#ros()}: a bridge's, a bag's, a bridged robot's replayed) offer theirs
 * too, by topic ({@code /odom:pose.pose.position.x}), for the robot of their envelope (none for a
 * bag's). Fed by the
 * Envelope stream (live or replayed alike); read by the plot view once per frame; exported as
 * CSV (time, one column per series).
 */
public final class FieldPlot implements EnvelopeSink {

    /** One plotted series: a robot (or none: a ROS 2 bag's topic) and a field path of a kind. */
    public record Series(int robotId, String kind, String path) {
        public String name() {
            return (robotId == Envelope.NO_ROBOT ? "" : "robot " + robotId + " ") + kind + ":" + path;
        }
    }

    private final MessageKinds kinds;
    private final int pointsPerSeries;
    private final long originMicros;
    /** The numeric paths of each kind seen; empty for a kind with none. */
    private final Map<String, List<String>> seenKinds = new TreeMap<>();
    private final List<Series> series = new CopyOnWriteArrayList<>();
    private final Map<Series, SeriesRing> rings = new java.util.HashMap<>();
    private long version;
    private long kindsVersion;

    public FieldPlot(MessageKinds kinds, int pointsPerSeries, long originMicros) {
        this.kinds = kinds;
        this.pointsPerSeries = pointsPerSeries;
        this.originMicros = originMicros;
    }

    @Override
    public void accept(Envelope e) {
        // a bag's ROS 2 channel belongs to no robot: plotted as robot -1
        if (e.direction() != Direction.IN || (e.robotId() < 0 && e.ros() == null)) {
            return;
        }
        Fumanoid.Message m = e.message() instanceof Fumanoid.Message f ? f : null;
        boolean foreign = e.ros() != null || (m == null && e.message() != null && e.channel() == Channel.BRIDGE);
        if (m == null && !foreign) {
            return;
        }
        String kind = e.kind();
        boolean known;
        synchronized (this) {
            known = seenKinds.containsKey(kind);
        }
        if (!known) {
            learn(kind, e);
        }
        if (series.isEmpty()) {
            return;
        }
        Message data = null;
        for (Series s : series) {
            if (s.robotId() != e.robotId() || !s.kind().equals(kind)) {
                continue;
            }
            double v;
            if (e.ros() != null) {
                v = e.ros().number(s.path());
            } else {
                if (data == null) {
                    data = m == null ? e.message() : dataOf(kind, m);
                    if (data == null) {
                        return;
                    }
                }
                v = NumericFields.value(data, s.path());
            }
            if (Double.isFinite(v)) {
                synchronized (this) {
                    SeriesRing ring = rings.get(s);
                    if (ring != null) {
                        ring.add((e.timeMicros() - originMicros) / 1e6, v);
                        version++;
                    }
                }
            }
        }
    }

    /** The numeric paths of a kind, from its first message: a ROS 2 or JSON message's own, else its protobuf type's. */
    private void learn(String kind, Envelope e) {
        List<String> paths;
        if (e.ros() != null) {
            paths = e.ros().numericPaths();
        } else if (e.channel() == Channel.BRIDGE) {
            paths = NumericFields.paths(e.message().getDescriptorForType());
        } else {
            FieldDescriptor ext = kinds.byName(kind).orElse(null);
            Descriptor type = ext != null && ext.getJavaType() == FieldDescriptor.JavaType.MESSAGE && !ext.isRepeated()
                    ? ext.getMessageType() : null;
            paths = type == null ? List.of() : NumericFields.paths(type);
        }
        synchronized (this) {
            seenKinds.put(kind, paths);
            kindsVersion++;
        }
    }

    private Message dataOf(String kind, Fumanoid.Message m) {
        FieldDescriptor ext = kinds.byName(kind).orElse(null);
        return ext == null || !m.hasField(ext) || !(m.getField(ext) instanceof Message data) ? null : data;
    }

    /** Every {@code kind:path} of the kinds seen so far, sorted; those containing {@code needle} (case ignored). */
    public synchronized List<String> paths(String needle) {
        String n = needle == null ? "" : needle.trim().toLowerCase(Locale.ROOT);
        List<String> out = new ArrayList<>();
        seenKinds.forEach((kind, paths) -> {
            for (String p : paths) {
                String full = kind + ":" + p;
                if (full.toLowerCase(Locale.ROOT).contains(n)) {
                    out.add(full);
                }
            }
        });
        return out;
    }

    /** Changes whenever a new kind was seen (the chooser's list grows). */
    public synchronized long kindsVersion() {
        return kindsVersion;
    }

    /** Adds a series for {@code robotId} and {@code kind:path}; false when it is no numeric path of a kind seen. */
    public boolean add(int robotId, String kindAndPath) {
        int colon = kindAndPath.indexOf(':');
        if (colon <= 0) {
            return false;
        }
        Series s = new Series(robotId, kindAndPath.substring(0, colon), kindAndPath.substring(colon + 1));
        synchronized (this) {
            List<String> paths = seenKinds.get(s.kind());
            if (paths == null || !paths.contains(s.path()) || rings.containsKey(s)) {
                return false;
            }
            rings.put(s, new SeriesRing(pointsPerSeries));
            series.add(s);
            version++;
        }
        return true;
    }

    public synchronized void remove(Series s) {
        if (rings.remove(s) != null) {
            series.remove(s);
            version++;
        }
    }

    public List<Series> series() {
        return List.copyOf(series);
    }

    public synchronized long version() {
        return version;
    }

    /** The series' points (oldest first), in the order they were added, in the plot store's form. */
    public synchronized List<PlotStore.SeriesData> snapshot() {
        List<PlotStore.SeriesData> out = new ArrayList<>(series.size());
        for (Series s : series) {
            double[][] xy = new double[2][];
            int n = rings.get(s).copyTo(xy);
            out.add(new PlotStore.SeriesData(s.name(), xy[0] == null ? new double[0] : xy[0],
                    xy[1] == null ? new double[0] : xy[1], n));
        }
        return out;
    }

    /**
     * The plotted data as CSV: a header ({@code time_s} and one column per series), then one
     * row per instant any series has a point, oldest first, empty where a series has none.
     */
    public String csv() {
        List<PlotStore.SeriesData> data = snapshot();
        TreeSet<Double> times = new TreeSet<>();
        for (PlotStore.SeriesData d : data) {
            for (int i = 0; i < d.count(); i++) {
                times.add(d.x()[i]);
            }
        }
        StringBuilder out = new StringBuilder("time_s");
        for (PlotStore.SeriesData d : data) {
            out.append(',').append(quote(d.name()));
        }
        out.append('\n');
        int[] at = new int[data.size()];
        for (double t : times) {
            out.append(String.format(Locale.ROOT, "%.6f", t));
            for (int k = 0; k < data.size(); k++) {
                PlotStore.SeriesData d = data.get(k);
                out.append(',');
                if (at[k] < d.count() && d.x()[at[k]] == t) {
                    out.append(number(d.y()[at[k]]));
                    at[k]++;
                    while (at[k] < d.count() && d.x()[at[k]] == t) {
                        at[k]++; // two points at one instant: the first is kept
                    }
                }
            }
            out.append('\n');
        }
        return out.toString();
    }

    private static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    private static String quote(String s) {
        return s.contains(",") || s.contains("\"") ? "\"" + s.replace("\"", "\"\"") + "\"" : s;
    }
}
