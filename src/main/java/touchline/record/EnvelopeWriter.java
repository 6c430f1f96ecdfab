package touchline.record;

import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.transport.remote.BridgedSchema;
import touchline.protocol.Framing;
import touchline.transport.Envelope;

import java.io.Closeable;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * Writes Envelopes to MCAP files (layout: {@link EnvelopeLayout}), starting a new file when
 * the current one exceeds the size or time limit. Log time = the envelope's time in ns;
 * publish time = the robot's own {@code timestamp} field (milliseconds, converted to ns)
 * where the message has one, else the log time. Protobuf channels carry the descriptor set
 * of {@code fumanoid.proto} plus every team file the message's extension comes from plus
 * the files given at construction. Single-threaded: {@link Recorder} owns one on its thread.
 */
public final class EnvelopeWriter implements Closeable {

    /**
     * Limits and tuning; 0 disables a split limit. {@code cameraIntervalMicros} thins camera
     * frames (NAO_CAMERA) to at most one per interval per channel; 0 keeps every frame.
     * {@code compression} is applied to every chunk.
     */
    public record Options(long splitBytes, long splitMicros, int chunkBytes, List<FileDescriptor> teamFiles,
                          long cameraIntervalMicros, ChunkCompression compression, BridgedSchema.Source bridged) {

        public Options(long splitBytes, long splitMicros, int chunkBytes, List<FileDescriptor> teamFiles) {
            this(splitBytes, splitMicros, chunkBytes, teamFiles, 0, ChunkCompression.NONE, BridgedSchema.Source.NONE);
        }

        public static Options defaults() {
            return new Options(0, 0, 512 * 1024, List.of(), 0, ChunkCompression.NONE, BridgedSchema.Source.NONE);
        }

        public Options withSplit(long bytes, long micros) {
            return new Options(bytes, micros, chunkBytes, teamFiles, cameraIntervalMicros, compression, bridged);
        }

        public Options withTeamFiles(List<FileDescriptor> files) {
            return new Options(splitBytes, splitMicros, chunkBytes, List.copyOf(files), cameraIntervalMicros, compression,
                    bridged);
        }

        /** Camera frames at most {@code fps} per second per camera channel (0 = all). */
        public Options withCameraRate(double fps) {
            return new Options(splitBytes, splitMicros, chunkBytes, teamFiles, fps <= 0 ? 0 : (long) (1e6 / fps),
                    compression, bridged);
        }

        public Options withCompression(ChunkCompression c) {
            return new Options(splitBytes, splitMicros, chunkBytes, teamFiles, cameraIntervalMicros, c, bridged);
        }

        /**
         * Bridged robots' channels ({@code Channel.BRIDGE}) recorded in their own encoding and schema
         * (ROS 2 {@code cdr}/{@code ros2msg}, {@code json}, {@code protobuf}), found in {@code source}.
         */
        public Options withBridgedSchemas(BridgedSchema.Source source) {
            return new Options(splitBytes, splitMicros, chunkBytes, teamFiles, cameraIntervalMicros, compression, source);
        }
    }

    /**
     * A small direct-mapped cache in front of {@code channels}: finds an envelope's channel by
     * comparing its fields in place, without building and hashing a {@link EnvelopeLayout.Key}
     * (which, for every recorded datagram, cost more than writing it).
     */
    private static final class RecentChannels {
        private static final int SIZE = 256;
        private final String[] kinds = new String[SIZE];
        private final int[] robots = new int[SIZE];
        private final int[] codes = new int[SIZE];
        private final java.net.InetSocketAddress[] peers = new java.net.InetSocketAddress[SIZE];
        private final ChannelState[] states = new ChannelState[SIZE];

        private static int code(Envelope e, String layout, Framing framing) {
            int l = layout == EnvelopeLayout.PAYLOAD ? 1 : layout == EnvelopeLayout.MALFORMED ? 2 : 3;
            return (((e.direction().ordinal() * 16 + e.channel().ordinal()) * 4 + l) * 4
                    + (framing == null ? 0 : framing.ordinal() + 1)) * 4 + e.origin().ordinal();
        }

        private static int slot(Envelope e) {
            int port = e.peer() == null ? 0 : e.peer().getPort();
            return (System.identityHashCode(e.kind()) * 31 + e.robotId() * 7 + port) & (SIZE - 1);
        }

        ChannelState find(Envelope e, String layout, Framing framing) {
            int i = slot(e);
            ChannelState s = states[i];
            return s != null && kinds[i] == e.kind() && robots[i] == e.robotId() && codes[i] == code(e, layout, framing)
                    && java.util.Objects.equals(peers[i], e.peer()) ? s : null;
        }

        void remember(Envelope e, String layout, Framing framing, ChannelState state) {
            int i = slot(e);
            kinds[i] = e.kind();
            robots[i] = e.robotId();
            codes[i] = code(e, layout, framing);
            peers[i] = e.peer();
            states[i] = state;
        }

        void clear() {
            java.util.Arrays.fill(states, null);
        }
    }

    /** The channel id in the current file, plus what finding the robot's timestamp needs. */
    private static final class ChannelState {
        final int id;
        long nextFrameMicros = Long.MIN_VALUE;
        RobotTimestamp timestamp;
        boolean timestampResolved;

        ChannelState(int id) {
            this.id = id;
        }
    }

    /** Opens the stream a file is written through (the recorder's is asynchronous). */
    @FunctionalInterface
    public interface FileOpener {
        java.io.OutputStream open(Path file) throws IOException;
    }

    private final Path base;
    private final Options options;
    private final FileOpener opener;
    private final List<Path> files = new ArrayList<>();
    private final Map<EnvelopeLayout.Key, ChannelState> channels = new HashMap<>();
    private final RecentChannels recent = new RecentChannels();
    private final Map<Set<String>, Integer> schemaIds = new HashMap<>();
    private final Map<String, Integer> bridgedSchemaIds = new HashMap<>();
    private McapWriter writer;
    private long fileStartMicros;
    private long bytesOfClosedFiles;
    private long thinnedFrames;

    public EnvelopeWriter(Path file, Options options) throws IOException {
        this(file, options, java.nio.file.Files::newOutputStream);
    }

    public EnvelopeWriter(Path file, Options options, FileOpener opener) throws IOException {
        this.base = file;
        this.options = options;
        this.opener = opener;
        openNext();
    }

    private void openNext() throws IOException {
        if (writer != null) {
            bytesOfClosedFiles += writer.size();
            writer.close();
        }
        Path next = files.isEmpty() ? base : numbered(base, files.size());
        writer = new McapWriter(opener.open(next), options.chunkBytes(), options.compression());
        files.add(next);
        channels.clear();
        recent.clear();
        schemaIds.clear();
        bridgedSchemaIds.clear();
        fileStartMicros = Long.MIN_VALUE;
    }

    static Path numbered(Path base, int n) {
        String name = base.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String stem = dot < 0 ? name : name.substring(0, dot);
        String ext = dot < 0 ? "" : name.substring(dot);
        return base.resolveSibling(String.format("%s-%03d%s", stem, n, ext));
    }

    public void write(Envelope e) throws IOException {
        if (fileStartMicros == Long.MIN_VALUE) {
            fileStartMicros = e.timeMicros();
        } else if ((options.splitBytes() > 0 && writer.size() >= options.splitBytes())
                || (options.splitMicros() > 0 && e.timeMicros() - fileStartMicros >= options.splitMicros())) {
            openNext();
            fileStartMicros = e.timeMicros();
        }
        String kindOfLayout = EnvelopeLayout.layoutOf(e);
        Framing framing = kindOfLayout == EnvelopeLayout.PAYLOAD ? EnvelopeLayout.exactFraming(e.raw()) : null;
        ChannelState channel = recent.find(e, kindOfLayout, framing);
        if (channel == null) {
            EnvelopeLayout.Key key = new EnvelopeLayout.Key(e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(),
                    kindOfLayout, framing, e.origin());
            channel = channels.get(key);
            if (channel == null) {
                BridgedSchema own = e.channel() == touchline.transport.Channel.BRIDGE && kindOfLayout == EnvelopeLayout.RAW
                        ? options.bridged().of(e.robotId(), e.kind()) : null;
                channel = own != null ? addBridgedChannel(key, own) : addChannel(key, e.message());
            }
            recent.remember(e, kindOfLayout, framing, channel);
        }
        if (options.cameraIntervalMicros() > 0 && e.channel() == touchline.transport.Channel.NAO_CAMERA
                && kindOfLayout != EnvelopeLayout.MALFORMED) {
            // one frame per interval slot, slots counted from the first frame, so 30 fps thinned
            // to 5 fps gives 5 frames a second rather than whatever divides 30 evenly
            long interval = options.cameraIntervalMicros();
            if (channel.nextFrameMicros != Long.MIN_VALUE && e.timeMicros() < channel.nextFrameMicros) {
                thinnedFrames++;
                return;
            }
            channel.nextFrameMicros = channel.nextFrameMicros == Long.MIN_VALUE
                    || channel.nextFrameMicros + interval <= e.timeMicros()
                    ? e.timeMicros() + interval : channel.nextFrameMicros + interval;
        }
        long logTime = e.timeMicros() * 1000;
        switch (kindOfLayout) {
            case EnvelopeLayout.PAYLOAD -> {
                int header = framing.headerSize();
                int length = EnvelopeLayout.frameEnd(e.raw()) - header; // a team key's trailer is not kept
                writer.addMessage(channel.id, logTime, robotTime(channel, e.message(), e.raw(), header, length, logTime),
                        e.raw(), header, length);
            }
            case EnvelopeLayout.MALFORMED -> writer.addMessage(channel.id, logTime, logTime,
                    EnvelopeLayout.malformedData(e.error(), e.raw()));
            default -> writer.addMessage(channel.id, logTime, logTime, e.raw());
        }
    }

    private ChannelState addChannel(EnvelopeLayout.Key key, Message message) {
        int schemaId = 0;
        if (key.layout().equals(EnvelopeLayout.PAYLOAD)) {
            Set<FileDescriptor> roots = new LinkedHashSet<>();
            roots.add(Fumanoid.getDescriptor());
            roots.addAll(options.teamFiles());
            for (FieldDescriptor f : message.getAllFields().keySet()) {
                roots.add(f.getFile());
            }
            Set<String> names = new TreeSet<>();
            roots.forEach(r -> names.add(r.getName()));
            schemaId = schemaIds.computeIfAbsent(names, n -> writer.addSchema(
                    Fumanoid.Message.getDescriptor().getFullName(), "protobuf",
                    SchemaSet.descriptorSet(roots).toByteArray()));
        }
        ChannelState state = new ChannelState(writer.addChannel(schemaId, key.topic(), key.encoding(), key.metadata()));
        channels.put(key, state);
        return state;
    }

    /** A bridged robot's channel in its own encoding and schema; Touchline's metadata still says whose it is. */
    private ChannelState addBridgedChannel(EnvelopeLayout.Key key, BridgedSchema own) {
        int schemaId = own.schemaName().isEmpty() ? 0 : bridgedSchemaIds.computeIfAbsent(
                own.schemaName() + "\n" + own.schemaEncoding() + "\n" + java.util.Arrays.hashCode(own.schemaData()),
                n -> writer.addSchema(own.schemaName(), own.schemaEncoding(), own.schemaData()));
        ChannelState state = new ChannelState(writer.addChannel(schemaId, key.topic(), own.messageEncoding(),
                key.metadata()));
        channels.put(key, state);
        return state;
    }

    /** The robot's own timestamp (ms) of the extension the message carries, in ns; else {@code fallback}. */
    private static long robotTime(ChannelState c, Message message, byte[] raw, int off, int len, long fallback) {
        if (!c.timestampResolved) {
            c.timestampResolved = true;
            c.timestamp = RobotTimestamp.of(message);
        }
        return c.timestamp == null ? fallback : c.timestamp.nanos(raw, off, len, fallback);
    }

    void metadataForTest(String name, Map<String, String> values) throws IOException {
        writer.addMetadata(name, values);
    }

    /** Writes the open chunk when it is older than {@code maxAgeNanos} (crash safety). */
    public void flushIfOlderThan(long maxAgeNanos) throws IOException {
        writer.flushIfOlderThan(maxAgeNanos);
    }

    public void flush() throws IOException {
        writer.flushChunk();
    }

    /** Bytes written to all files so far (including the open chunk). */
    public long bytes() {
        return writer.size() + bytesOfClosedFiles;
    }

    /** Camera frames left out by the camera rate limit. */
    public long thinnedFrames() {
        return thinnedFrames;
    }

    public List<Path> files() {
        return Collections.unmodifiableList(files);
    }

    @Override
    public void close() throws IOException {
        writer.close();
    }
}
