package touchline.record;

import touchline.protocol.MessageKinds;
import touchline.transport.Envelope;
import touchline.transport.GameStateReader;

import java.io.Closeable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.PriorityQueue;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * One replay from one or several recordings (the laptop's and robots' own logs) on one
 * timeline: the files' envelopes in one merged order of time, each file's times moved onto
 * the first file's clock by its {@linkplain ClockAlignment.Offset offset}. The offset is the
 * one the user gives, or else estimated from the GameController packets both files heard
 * ({@link ClockAlignment}); without either the file plays unaligned (offset 0) and says so.
 * A robot heard in two files is one robot: the envelopes carry its robot number, nothing of
 * the file; which file an envelope came from is {@link Cursor#source()}.
 */
public final class ReplaySession implements Closeable {

    /** One file of the session: its name (as shown), the recording and how its clock was aligned. */
    public record Part(String name, Recording recording, ClockAlignment.Offset offset) { }

    private final List<Part> parts;
    private final CopyOnWriteArrayList<String> notes = new CopyOnWriteArrayList<>();
    private List<TimelineEvent> events; // guarded by this

    /**
     * The most GameController packets of one file an alignment weighs: 200 000 are 28 hours of
     * one GameController's, kept in 3.2 MB (a hash and a time each); those beyond are said.
     */
    static final int MAX_ALIGNMENT_PACKETS = 200_000;

    private ReplaySession(List<Part> parts, List<String> notes) {
        this.parts = List.copyOf(parts);
        this.notes.addAll(notes);
    }

    /** A session of one recording, on its own clock. */
    public static ReplaySession of(Recording recording) {
        return new ReplaySession(List.of(new Part("", recording, ClockAlignment.Offset.REFERENCE)), List.of());
    }

    /**
     * Opens {@code files} as one session. A file's offset in {@code given} (its clock minus
     * the first file's, in µs; keyed by the path as given) wins; the others are estimated from
     * the GameController packets they share with the first file (one pass over each file).
     */
    public static ReplaySession open(List<Path> files, Map<Path, Long> given, MessageKinds kinds)
            throws RecordingException {
        return open(files, given, kinds, ExpansionLimit.DEFAULT);
    }

    /** Opens {@code files} as {@link #open(List, Map, MessageKinds)} does, each read no further than {@code limit} allows. */
    public static ReplaySession open(List<Path> files, Map<Path, Long> given, MessageKinds kinds,
                                     ExpansionLimit limit) throws RecordingException {
        if (files.isEmpty()) {
            throw new IllegalArgumentException("a session needs at least one file");
        }
        List<Recording> opened = new ArrayList<>();
        try {
            for (Path f : files) {
                try {
                    opened.add(Recording.open(f, kinds, limit));
                } catch (RecordingException e) {
                    throw files.size() == 1 ? e : new RecordingException(f.getFileName() + ": " + e.getMessage());
                }
            }
        } catch (RecordingException | RuntimeException e) {
            opened.forEach(Recording::close);
            throw e;
        }
        if (files.size() == 1 && !given.containsKey(files.get(0))) {
            return of(opened.get(0));
        }
        ClockAlignment alignment = new ClockAlignment();
        ClockAlignment.Packets reference = null;
        List<Part> parts = new ArrayList<>();
        List<String> notes = new ArrayList<>();
        for (int i = 0; i < files.size(); i++) {
            Path f = files.get(i);
            Long offset = given.get(f);
            ClockAlignment.Offset o;
            if (offset != null) {
                o = ClockAlignment.Offset.given(offset);
            } else if (i == 0) {
                o = ClockAlignment.Offset.REFERENCE;
            } else {
                if (reference == null) {
                    reference = gameControllerPackets(opened.get(0), files.get(0), notes);
                }
                o = alignment.estimate(reference, gameControllerPackets(opened.get(i), f, notes));
            }
            parts.add(new Part(f.getFileName().toString(), opened.get(i), o));
        }
        return new ReplaySession(parts, notes);
    }

    /**
     * The GameController game-state datagrams in {@code r} (any format Touchline recognises),
     * the first {@link #MAX_ALIGNMENT_PACKETS} of them; more are said in {@code notes}.
     */
    static ClockAlignment.Packets gameControllerPackets(Recording r, Path file, List<String> notes) {
        ClockAlignment.Packets packets = new ClockAlignment.Packets(MAX_ALIGNMENT_PACKETS);
        Recording.Cursor c = r.cursor(Long.MIN_VALUE);
        for (Envelope e = c.next(); e != null; e = c.next()) {
            if (GameStateReader.isGameState(e)) {
                packets.add(e.timeMicros(), e.raw());
            }
        }
        if (packets.refused() > 0) {
            notes.add(file.getFileName() + ": its clock is aligned by its first " + MAX_ALIGNMENT_PACKETS
                    + " GameController packets; " + packets.refused() + " later ones are not weighed");
        }
        return packets;
    }

    public List<Part> parts() {
        return parts;
    }

    /** The first file's recording (the one whose clock the session keeps). */
    public Recording first() {
        return parts.get(0).recording();
    }

    public long startMicros() {
        long start = Long.MAX_VALUE;
        for (Part p : parts) {
            start = Math.min(start, p.recording().startMicros() - p.offset().offsetMicros());
        }
        return start;
    }

    public long endMicros() {
        long end = Long.MIN_VALUE;
        for (Part p : parts) {
            end = Math.max(end, p.recording().endMicros() - p.offset().offsetMicros());
        }
        return end;
    }

    public long durationMicros() {
        return endMicros() - startMicros();
    }

    /** Problems with the files and with what was read so far; prefixed with the file's name in a session of several. */
    public List<String> problems() {
        List<String> all = new ArrayList<>();
        for (Part p : parts) {
            for (String problem : p.recording().problems()) {
                all.add(parts.size() > 1 ? p.name() + ": " + problem : problem);
            }
        }
        all.addAll(notes);
        return all;
    }

    /**
     * Everything to say about the files: problems, channels skipped with their counts,
     * attachments and metadata, each named with its file in a session of several.
     */
    public ReplayNotes notes() {
        ReplayNotes all = parts.size() == 1 ? first().notes() : ReplayNotes.NONE;
        if (parts.size() > 1) {
            for (Part p : parts) {
                all = all.plus(p.recording().notes().inFile(p.name()));
            }
        }
        return notes.isEmpty() ? all
                : all.plus(new ReplayNotes(List.copyOf(notes), List.of(), List.of(), java.util.Map.of(), true));
    }

    /** Adds a problem found while playing (once per distinct sentence). */
    void note(String problem) {
        if (parts.size() == 1) {
            first().note(problem);
        } else {
            notes.addIfAbsent(problem);
        }
    }

    /** Timeline events of the merged stream (one pass over every file, done once). */
    public synchronized List<TimelineEvent> events() {
        if (parts.size() == 1 && parts.get(0).offset().offsetMicros() == 0) {
            return first().events();
        }
        if (events == null) { // read once, by the first caller; later callers wait for it rather than read again
            events = EventDetector.scan(cursor(Long.MIN_VALUE)::next);
        }
        return events;
    }

    /** Envelopes of every file from the first with (session) time >= {@code fromMicros}, merged by time. */
    public Cursor cursor(long fromMicros) {
        return new Cursor(fromMicros);
    }

    /** The merged envelopes; {@link #next()} returns null at the end. One thread per cursor. */
    public final class Cursor {
        private record Head(Envelope envelope, int part) { }

        private final Recording.Cursor[] cursors = new Recording.Cursor[parts.size()];
        private final PriorityQueue<Head> heads = new PriorityQueue<>((a, b) -> {
            int c = Long.compare(a.envelope().timeMicros(), b.envelope().timeMicros());
            return c != 0 ? c : Integer.compare(a.part(), b.part());
        });
        private final boolean single;
        private String source = "";

        private Cursor(long fromMicros) {
            single = parts.size() == 1 && parts.get(0).offset().offsetMicros() == 0;
            for (int i = 0; i < cursors.length; i++) {
                long offset = parts.get(i).offset().offsetMicros();
                long from = fromMicros <= Long.MIN_VALUE / 2 ? Long.MIN_VALUE : fromMicros + offset;
                cursors[i] = parts.get(i).recording().cursor(from);
                if (!single) {
                    refill(i);
                }
            }
            if (single) {
                source = parts.get(0).name();
            }
        }

        private void refill(int i) {
            Envelope e = cursors[i].next();
            if (e != null) {
                long offset = parts.get(i).offset().offsetMicros();
                heads.add(new Head(offset == 0 ? e : shifted(e, -offset), i));
            }
        }

        public Envelope next() {
            if (single) {
                return cursors[0].next();
            }
            Head h = heads.poll();
            if (h == null) {
                return null;
            }
            refill(h.part());
            source = parts.get(h.part()).name();
            return h.envelope();
        }

        /** The name of the file the envelope last returned came from ("" for a session of one file). */
        public String source() {
            return source;
        }
    }

    private static Envelope shifted(Envelope e, long byMicros) {
        return new Envelope(e.timeMicros() + byMicros, e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(),
                e.message(), e.raw(), e.error(), e.origin());
    }

    @Override
    public void close() {
        parts.forEach(p -> p.recording().close());
    }
}
