package touchline.record;

import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.Message;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.transport.Envelope;

import java.io.Closeable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * An MCAP recording read back as Envelopes, equal (time, direction, channel, peer, robot,
 * kind, error, raw bytes) to the ones recorded. FUmanoids payloads are decoded again with
 * the message kinds given (Touchline's own plus the team types the recording carries in
 * its schemas), so consumers get {@link Envelope#message()} as from a live transport.
 * Channels written by other tools (no Touchline metadata) play as {@link touchline.transport.Channel#FOREIGN}
 * envelopes where they can (protobuf with its schema in the file; ROS 2 CDR by its ros2msg or ros2idl
 * definition and JSON, decoded into {@link Envelope#ros()}); the others are
 * skipped and counted per channel in {@link #notes()}.
 */
public final class Recording implements Closeable {

    /** Channel metadata key of the standard-schema channels an export adds (not envelopes; replay skips them). */
    public static final String STANDARD_CHANNEL = "touchline.standard";

    private final McapReader mcap;
    private final MessageCodec codec;
    private final EnvelopeLayout layout = new EnvelopeLayout();
    private final Map<Integer, ChannelReading> readings = new ConcurrentHashMap<>();
    private final Map<Integer, ChannelReading.Skipped> skipped = Collections.synchronizedMap(new java.util.TreeMap<>());
    private final SchemaSet types = new SchemaSet();
    private final CopyOnWriteArrayList<String> problems = new CopyOnWriteArrayList<>();
    private final List<FileDescriptorSet> schemas = new ArrayList<>();
    private volatile List<TimelineEvent> events;

    private Recording(McapReader mcap, MessageKinds kinds) {
        this.mcap = mcap;
        this.codec = new MessageCodec(kinds);
        loadSchemas(kinds);
        mcap.channels().values().forEach(this::reading);
    }

    public static Recording open(Path file) throws RecordingException {
        return open(file, new MessageKinds());
    }

    /** Opens {@code file}; team types found in its schemas are added to {@code kinds}. */
    public static Recording open(Path file, MessageKinds kinds) throws RecordingException {
        return open(file, kinds, ExpansionLimit.DEFAULT);
    }

    /** Opens {@code file} as {@link #open(Path, MessageKinds)} does, reading no more than {@code limit} lets it expand to. */
    public static Recording open(Path file, MessageKinds kinds, ExpansionLimit limit) throws RecordingException {
        return new Recording(McapReader.open(file, limit), kinds);
    }

    private void loadSchemas(MessageKinds kinds) {
        SchemaSet known = types;
        Map<FileDescriptor, String> schemaOf = new java.util.LinkedHashMap<>();
        for (McapReader.Schema s : mcap.schemas().values()) {
            if (!s.encoding().equals("protobuf")) {
                continue;
            }
            try {
                FileDescriptorSet set = FileDescriptorSet.parseFrom(s.data());
                schemas.add(set);
                for (FileDescriptor f : known.add(set)) {
                    schemaOf.put(f, s.name());
                }
            } catch (InvalidProtocolBufferException | RecordingException e) {
                problems.addIfAbsent("schema " + s.id() + " (" + s.name() + ") in the recording does not parse ("
                        + e.getMessage() + "); its messages play as raw bytes with the built-in types"
                        + " (those of another tool's channel are skipped)");
            }
        }
        // every file of every schema at once: one registry build for the recording, not one per file
        kinds.add(schemaOf.keySet()).forEach((f, refused) ->
                problems.addIfAbsent("schema " + schemaOf.get(f) + ": " + refused));
    }

    /** The FileDescriptorSets the recording was made with (one per protobuf schema that parses). */
    public List<FileDescriptorSet> schemas() {
        return Collections.unmodifiableList(schemas);
    }

    public long startMicros() {
        return mcap.startTime() / 1000;
    }

    public long endMicros() {
        return mcap.endTime() / 1000;
    }

    public long durationMicros() {
        return endMicros() - startMicros();
    }

    /** Problems with the file and with what was read so far, one user-facing sentence each. */
    public List<String> problems() {
        List<String> all = new ArrayList<>(mcap.problems());
        all.addAll(problems);
        return all;
    }

    /**
     * The notes as they stand: problems, channels skipped with their message counts (final
     * once the file's statistics give them or the whole file has been read), attachments and
     * metadata records.
     */
    public ReplayNotes notes() {
        List<ReplayNotes.SkippedChannel> s = new ArrayList<>();
        synchronized (skipped) {
            skipped.forEach((id, k) -> s.add(new ReplayNotes.SkippedChannel(k.topic(), k.encoding(), k.reason(),
                    mcap.messages(id))));
        }
        return new ReplayNotes(problems(), s, mcap.attachments(), mcap.metadata(), mcap.messageCountsFinal());
    }

    /** Adds a problem found while playing (once per distinct sentence). */
    void note(String problem) {
        problems.addIfAbsent(problem);
    }

    public McapReader mcap() {
        return mcap;
    }

    /** Events for a timeline (goals, game state changes, robots lost), found by reading the file once. */
    public List<TimelineEvent> events() {
        List<TimelineEvent> e = events;
        if (e == null) {
            e = EventDetector.scan(cursor(Long.MIN_VALUE)::next);
            events = e;
        }
        return e;
    }

    /** Envelopes from the first with time >= {@code fromMicros}, in file order. */
    public Cursor cursor(long fromMicros) {
        long from = fromMicros <= Long.MIN_VALUE / 1000 ? Long.MIN_VALUE : fromMicros * 1000;
        return new Cursor(mcap.cursor(from == Long.MIN_VALUE ? 0 : from));
    }

    /** Reads Envelopes; {@link #next()} returns null at the end. One thread per cursor. */
    public final class Cursor {
        private final McapReader.Cursor messages;

        private Cursor(McapReader.Cursor messages) {
            this.messages = messages;
        }

        public Envelope next() {
            for (McapReader.McapMessage m = messages.next(); m != null; m = messages.next()) {
                Envelope e = toEnvelope(m);
                if (e != null) {
                    return e;
                }
            }
            return null;
        }
    }

    /**
     * The envelope a message of {@link #mcap()} holds, or null when it holds none: a channel
     * skipped (counted in {@link #notes()}) or a standard-schema channel an export added beside
     * the recorded ones (metadata {@value #STANDARD_CHANNEL}, skipped quietly).
     */
    public Envelope toEnvelope(McapReader.McapMessage m) {
        ChannelReading reading = readings.get(m.channelId());
        if (reading == null) {
            McapReader.ChannelInfo info = mcap.channels().get(m.channelId());
            if (info == null) {
                problems.addIfAbsent("messages on channel " + m.channelId() + " without a channel record are skipped");
                return null;
            }
            if (info.metadata().containsKey(STANDARD_CHANNEL)) {
                return null;
            }
            reading = reading(info);
        }
        long time = m.logTime() / 1000;
        if (reading instanceof ChannelReading.Foreign f) {
            return f.envelope(time, m.data());
        }
        if (reading instanceof ChannelReading.Bridged b) {
            return b.envelope(time, m.data());
        }
        if (reading instanceof ChannelReading.Decoded d) {
            return d.envelope(time, m.data());
        }
        if (!(reading instanceof ChannelReading.Touchline t)) {
            return null;
        }
        EnvelopeLayout.Key key = t.key();
        switch (key.layout()) {
            case EnvelopeLayout.PAYLOAD -> {
                byte[] raw = layout.frame(key.framing(), m.data());
                Message message = codec.decode(m.data()) instanceof MessageResult.Decoded d ? d.message() : null;
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        message, raw, null, key.origin());
            }
            case EnvelopeLayout.MALFORMED -> {
                Object[] parts = EnvelopeLayout.parseMalformed(m.data());
                if (parts == null) {
                    problems.addIfAbsent("a malformed-datagram record on " + key.topic() + " is too short; skipped");
                    return null;
                }
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        null, (byte[]) parts[1], (String) parts[0], key.origin());
            }
            default -> {
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        null, m.data(), null, key.origin());
            }
        }
    }

    /** How {@code info}'s messages are read, decided once per channel; skipped channels are listed in the notes. */
    private ChannelReading reading(McapReader.ChannelInfo info) {
        return readings.computeIfAbsent(info.id(), id -> {
            ChannelReading r = ChannelReading.of(info, mcap.schemas().get(info.schemaId()), this::type, codec);
            if (r instanceof ChannelReading.Skipped k) {
                skipped.put(id, k);
            }
            return r;
        });
    }

    /** The message type {@code fullName} (nested types too) among the recording's schemas and the built-in ones. */
    private com.google.protobuf.Descriptors.Descriptor type(String fullName) {
        for (FileDescriptor f : types.files()) {
            if (!f.getPackage().isEmpty() && !fullName.startsWith(f.getPackage() + ".")) {
                continue;
            }
            java.util.ArrayDeque<com.google.protobuf.Descriptors.Descriptor> todo =
                    new java.util.ArrayDeque<>(f.getMessageTypes());
            while (!todo.isEmpty()) {
                com.google.protobuf.Descriptors.Descriptor d = todo.poll();
                if (d.getFullName().equals(fullName)) {
                    return d;
                }
                if (fullName.startsWith(d.getFullName() + ".")) {
                    todo.addAll(d.getNestedTypes());
                }
            }
        }
        return null;
    }

    @Override
    public void close() {
        mcap.close();
    }
}
