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
 * Channels written by other tools (no Touchline metadata) are skipped with a note.
 */
public final class Recording implements Closeable {

    /** Channel metadata key of the standard-schema channels an export adds (not envelopes; replay skips them). */
    public static final String STANDARD_CHANNEL = "touchline.standard";

    private final McapReader mcap;
    private final MessageCodec codec;
    private final EnvelopeLayout layout = new EnvelopeLayout();
    private final Map<Integer, EnvelopeLayout.Key> keys = new ConcurrentHashMap<>();
    private final CopyOnWriteArrayList<String> problems = new CopyOnWriteArrayList<>();
    private final List<FileDescriptorSet> schemas = new ArrayList<>();
    private volatile List<TimelineEvent> events;

    private Recording(McapReader mcap, MessageKinds kinds) {
        this.mcap = mcap;
        this.codec = new MessageCodec(kinds);
        loadSchemas(kinds);
    }

    public static Recording open(Path file) throws RecordingException {
        return open(file, new MessageKinds());
    }

    /** Opens {@code file}; team types found in its schemas are added to {@code kinds}. */
    public static Recording open(Path file, MessageKinds kinds) throws RecordingException {
        return new Recording(McapReader.open(file), kinds);
    }

    private void loadSchemas(MessageKinds kinds) {
        SchemaSet known = new SchemaSet();
        for (McapReader.Schema s : mcap.schemas().values()) {
            if (!s.encoding().equals("protobuf")) {
                continue;
            }
            try {
                FileDescriptorSet set = FileDescriptorSet.parseFrom(s.data());
                schemas.add(set);
                for (FileDescriptor f : known.add(set)) {
                    kinds.add(f).ifPresent(refused -> problems.addIfAbsent("schema " + s.name() + ": " + refused));
                }
            } catch (InvalidProtocolBufferException | RecordingException e) {
                problems.addIfAbsent("schema " + s.id() + " (" + s.name() + ") in the recording does not parse ("
                        + e.getMessage() + "); its messages play as raw bytes with the built-in types");
            }
        }
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
     * Touchline did not write (noted in {@link #problems()}) or a standard-schema channel an
     * export added beside the recorded ones (metadata {@value #STANDARD_CHANNEL}, skipped quietly).
     */
    public Envelope toEnvelope(McapReader.McapMessage m) {
        EnvelopeLayout.Key key = keys.get(m.channelId());
        if (key == null) {
            McapReader.ChannelInfo info = mcap.channels().get(m.channelId());
            if (info == null) {
                problems.addIfAbsent("messages on channel " + m.channelId() + " without a channel record are skipped");
                return null;
            }
            if (info.metadata().containsKey(STANDARD_CHANNEL)) {
                return null;
            }
            try {
                key = EnvelopeLayout.Key.fromMetadata(info.metadata());
            } catch (RuntimeException e) {
                problems.addIfAbsent("channel " + info.topic() + " was not written by Touchline (" + e.getMessage()
                        + "); its messages are skipped");
                return null;
            }
            keys.put(m.channelId(), key);
        }
        long time = m.logTime() / 1000;
        switch (key.layout()) {
            case EnvelopeLayout.PAYLOAD -> {
                byte[] raw = layout.frame(key.framing(), m.data());
                Message message = codec.decode(m.data()) instanceof MessageResult.Decoded d ? d.message() : null;
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        message, raw, null);
            }
            case EnvelopeLayout.MALFORMED -> {
                Object[] parts = EnvelopeLayout.parseMalformed(m.data());
                if (parts == null) {
                    problems.addIfAbsent("a malformed-datagram record on " + key.topic() + " is too short; skipped");
                    return null;
                }
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        null, (byte[]) parts[1], (String) parts[0]);
            }
            default -> {
                return new Envelope(time, key.direction(), key.channel(), key.peer(), key.robotId(), key.kind(),
                        null, m.data(), null);
            }
        }
    }

    @Override
    public void close() {
        mcap.close();
    }
}
