package touchline.fuzz;

import touchline.bench.record.SyntheticTeam;
import touchline.protocol.MessageKinds;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.RecordingException;
import touchline.record.ReplaySession;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * A recording as {@code replay} opens it: one MCAP file, or two played as one session (their
 * clocks aligned by the GameController packets they share), through the public
 * {@link ReplaySession#open} and read to the end. The input is a file, or — when its first
 * byte is odd — a 4-byte big-endian length and then two files. A file the reader refuses
 * ({@link RecordingException}) is the declared outcome; anything else thrown, a stall past the
 * fuzzer's 10 s or an out-of-memory is a finding. Seeds are the console's own recordings in
 * every chunk compression (none, zstd, lz4), several chunks each.
 */
final class RecordingTarget implements FuzzTarget {

    private static final long START = 1_760_000_000_000_000L;

    private final Path dir;

    RecordingTarget() {
        try {
            dir = Files.createTempDirectory("touchline-fuzz-recording");
            dir.toFile().deleteOnExit();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Override
    public String name() {
        return "recording";
    }

    @Override
    public void accept(byte[] input) {
        List<Path> files = new ArrayList<>();
        try {
            if (input.length > 0 && (input[0] & 1) == 1 && input.length >= 5) {
                int first = (int) Math.min(Integer.toUnsignedLong(ByteBuffer.wrap(input, 1, 4).getInt()),
                        input.length - 5L);
                files.add(write("a.mcap", Arrays.copyOfRange(input, 5, 5 + first)));
                files.add(write("b.mcap", Arrays.copyOfRange(input, 5 + first, input.length)));
            } else {
                files.add(write("a.mcap", input));
            }
            try (ReplaySession session = ReplaySession.open(files, Map.of(), new MessageKinds())) {
                ReplaySession.Cursor c = session.cursor(Long.MIN_VALUE);
                for (Envelope e = c.next(); e != null; e = c.next()) {
                    e.timeMicros(); // every envelope is read, as the replay plays it
                }
                session.events();
                session.problems();
                session.notes();
            }
        } catch (RecordingException refused) {
            // the reader's declared answer to a file it cannot use
        } catch (IOException e) {
            throw new UncheckedIOException("the fuzz harness's temporary files", e);
        } finally {
            for (Path f : files) {
                f.toFile().delete();
            }
        }
    }

    private Path write(String name, byte[] bytes) throws IOException {
        return Files.write(dir.resolve(name), bytes);
    }

    /** Each compression: a team's second as one file, and a laptop's and a robot's file as two. */
    @Override
    public List<byte[]> seeds() {
        List<byte[]> seeds = new ArrayList<>();
        try {
            List<Envelope> team = new ArrayList<>();
            new SyntheticTeam(2, START, 42).generate(1, team::add);
            List<Envelope> robot = team.stream().filter(e -> e.robotId() == 2 || e.channel() == Channel.GAMECONTROLLER)
                    .map(e -> new Envelope(e.timeMicros() + 1_250_000, e.direction(), e.channel(), e.peer(),
                            e.robotId(), e.kind(), e.message(), e.raw(), e.error()))
                    .toList();
            for (ChunkCompression c : ChunkCompression.values()) {
                EnvelopeWriter.Options options = new EnvelopeWriter.Options(0, 0, 4096, List.of()).withCompression(c);
                byte[] laptop = recorded(team, options);
                seeds.add(laptop);
                byte[] other = recorded(robot, options);
                ByteBuffer two = ByteBuffer.allocate(5 + laptop.length + other.length);
                two.put((byte) 1).putInt(laptop.length).put(laptop).put(other);
                seeds.add(two.array());
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return seeds;
    }

    private byte[] recorded(List<Envelope> envelopes, EnvelopeWriter.Options options) throws IOException {
        Path f = dir.resolve("seed.mcap");
        try (EnvelopeWriter w = new EnvelopeWriter(f, options)) {
            for (Envelope e : envelopes) {
                w.write(e);
            }
        }
        byte[] bytes = Files.readAllBytes(f);
        Files.delete(f);
        return bytes;
    }
}
