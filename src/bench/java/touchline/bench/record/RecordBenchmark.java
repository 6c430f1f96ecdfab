package touchline.bench.record;

import picocli.CommandLine;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.PlaybackClock;
import touchline.record.Player;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.record.Recording;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeBus;

import java.io.BufferedOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The recording budgets, each against a baseline measured in the same run: writer
 * messages/s (vs the same bytes to a BufferedOutputStream), headless replay speed of a
 * one-hour six-robot recording (vs reading the file's bytes), seek time in that file, and
 * the cost the recorder adds on the publishing (network) thread (bus with vs without it).
 * Usage: {@code java ... touchline.bench.record.RecordBenchmark [DIR]}, or as the picocli
 * subcommand {@code bench record [--dir DIR]}.
 */
@CommandLine.Command(name = "record", mixinStandardHelpOptions = true,
        description = "Writer messages/s, headless replay speed and seek time of a one-hour six-robot recording.")
public final class RecordBenchmark implements Callable<Integer> {

    @CommandLine.Option(names = "--dir", description = "where the benchmark files go (default: a temporary directory)")
    Path dir;

    @CommandLine.Option(names = "--compression", defaultValue = "NONE",
            description = "chunk compression of the files written: NONE, ZSTD or LZ4 (default: ${DEFAULT-VALUE})")
    ChunkCompression compression = ChunkCompression.NONE;

    public static void main(String[] args) throws Exception {
        RecordBenchmark bench = new RecordBenchmark();
        bench.dir = args.length > 0 ? Path.of(args[0]) : null;
        bench.call();
    }

    @Override
    public Integer call() throws Exception {
        Path dir = this.dir != null ? this.dir : Files.createTempDirectory("touchline-bench");
        Files.createDirectories(dir);
        System.out.println("generating one hour of a six-robot team ...");
        List<Envelope> hour = new ArrayList<>();
        new SyntheticTeam(6, 1_760_000_000_000_000L, 3).generate(3600, hour::add);
        long bytes = hour.stream().mapToLong(e -> e.raw().length).sum();
        System.out.printf("%d envelopes, %.1f MB of datagrams%n", hour.size(), bytes / 1e6);

        Path file = dir.resolve("bench-hour.mcap");
        Path base = dir.resolve("bench-baseline.bin");
        double writer = 0;
        double baseline = 0;
        for (int round = 0; round < 3; round++) {
            baseline = Math.max(baseline, baselineWrite(hour, base));
            writer = Math.max(writer, writeMcap(hour, file));
        }
        System.out.printf("writer: %.0f messages/s (baseline BufferedOutputStream %.0f/s, ratio %.2f); file %.1f MB%n",
                writer, baseline, writer / baseline, Files.size(file) / 1e6);

        double recorder = recorderThroughput(hour, dir.resolve("bench-recorder.mcap"));
        System.out.printf("recorder (encoding on the publishing thread, chunks to the disk thread, until the file is closed): %.0f messages/s%n", recorder);

        double[] overhead = publishOverhead(hour, dir.resolve("bench-overhead.mcap"));
        System.out.printf("publishing thread: %.0f ns/envelope bus alone, %.0f ns with the recorder subscribed "
                + "(+%.0f%%), %d dropped of %d%n", overhead[0], overhead[1], 100 * (overhead[1] / overhead[0] - 1),
                (long) overhead[2], hour.size());

        double readSeconds = Double.MAX_VALUE;
        double replaySeconds = Double.MAX_VALUE;
        long delivered = 0;
        for (int round = 0; round < 3; round++) {
            readSeconds = Math.min(readSeconds, readBytes(file));
            UnpacedReplay run = UnpacedReplay.intoNothing(file);
            replaySeconds = Math.min(replaySeconds, run.seconds());
            delivered = run.envelopes();
        }
        System.out.printf("replay headless: %d envelopes of one hour in %.2f s = %.0fx real time "
                + "(reading the file's bytes alone: %.2f s, ratio %.1f)%n", delivered, replaySeconds, 3600 / replaySeconds,
                readSeconds, replaySeconds / readSeconds);

        try (Recording r = Recording.open(file)) {
            long t0 = System.nanoTime();
            int events = r.events().size();
            System.out.printf("timeline events: %d found in %.2f s (one pass over the file, done once per open)%n",
                    events, (System.nanoTime() - t0) / 1e9);
            Random random = new Random(1);
            long[] seeks = new long[50];
            List<Envelope> got = new ArrayList<>();
            Player p = new Player(r, got::add, new touchline.app.SystemClock());
            for (int i = 0; i < seeks.length; i++) {
                long target = r.startMicros() + (long) (random.nextDouble() * r.durationMicros());
                long t1 = System.nanoTime();
                p.seek(target);
                got.clear();
                p.runFor(1);
                seeks[i] = System.nanoTime() - t1;
                if (got.isEmpty() || got.get(0).timeMicros() < target) {
                    throw new IllegalStateException("seek to " + target + " landed wrong: " + got);
                }
            }
            Arrays.sort(seeks);
            System.out.printf("seek (to a random time, until the first envelope is delivered): median %.1f ms, max %.1f ms%n",
                    seeks[seeks.length / 2] / 1e6, seeks[seeks.length - 1] / 1e6);
        }
        if (this.dir == null) {
            try (var files = Files.list(dir)) {
                for (Path f : files.toList()) {
                    Files.delete(f);
                }
            }
            Files.delete(dir);
        }
        return 0;
    }

    private EnvelopeWriter.Options options() {
        return EnvelopeWriter.Options.defaults().withCompression(compression);
    }

    private static double baselineWrite(List<Envelope> hour, Path file) throws IOException {
        long t0 = System.nanoTime();
        try (DataOutputStream out = new DataOutputStream(new BufferedOutputStream(Files.newOutputStream(file), 1 << 16))) {
            for (Envelope e : hour) {
                out.writeLong(e.timeMicros());
                out.writeInt(e.raw().length);
                out.write(e.raw());
            }
        }
        return hour.size() / ((System.nanoTime() - t0) / 1e9);
    }

    private double writeMcap(List<Envelope> hour, Path file) throws IOException {
        long t0 = System.nanoTime();
        try (EnvelopeWriter w = new EnvelopeWriter(file, options())) {
            for (Envelope e : hour) {
                w.write(e);
            }
        }
        return hour.size() / ((System.nanoTime() - t0) / 1e9);
    }

    private double recorderThroughput(List<Envelope> hour, Path file) throws IOException {
        long t0 = System.nanoTime();
        Recorder recorder = new Recorder(file, options());
        hour.forEach(recorder::accept);
        recorder.close();
        return recorder.stats().written() / ((System.nanoTime() - t0) / 1e9);
    }

    private double[] publishOverhead(List<Envelope> hour, Path file) throws Exception {
        AtomicLong sink = new AtomicLong();
        EnvelopeBus alone = new EnvelopeBus();
        alone.subscribe(e -> sink.addAndGet(e.raw().length));
        EnvelopeBus with = new EnvelopeBus();
        with.subscribe(e -> sink.addAndGet(e.raw().length));
        double bestAlone = Double.MAX_VALUE;
        double bestWith = Double.MAX_VALUE;
        long dropped = 0;
        for (int round = 0; round < 3; round++) {
            bestAlone = Math.min(bestAlone, publish(alone, hour));
            Recorder recorder = new Recorder(file, options());
            try (AutoCloseable s = with.subscribe(recorder)) {
                bestWith = Math.min(bestWith, publish(with, hour));
            }
            recorder.close();
            RecorderStats stats = recorder.stats();
            dropped = stats.dropped();
        }
        return new double[]{bestAlone, bestWith, dropped};
    }

    /** Publishes at about 100 000 envelopes/s (a busy network thread), returns ns spent per envelope. */
    private static double publish(EnvelopeBus bus, List<Envelope> hour) {
        long busy = 0;
        long next = System.nanoTime();
        for (int i = 0; i < hour.size(); i++) {
            if ((i & 1023) == 0) {
                next += 10_240_000L; // 1024 envelopes per 10.24 ms
                while (System.nanoTime() < next) {
                    Thread.onSpinWait();
                }
            }
            long t0 = System.nanoTime();
            bus.accept(hour.get(i));
            busy += System.nanoTime() - t0;
        }
        return (double) busy / hour.size();
    }

    private static double readBytes(Path file) throws IOException {
        long t0 = System.nanoTime();
        byte[] buf = new byte[1 << 16];
        long sum = 0;
        try (InputStream in = Files.newInputStream(file)) {
            for (int n; (n = in.read(buf)) > 0; ) {
                sum += buf[n - 1];
            }
        }
        if (sum == 42) {
            System.out.print("");
        }
        return (System.nanoTime() - t0) / 1e9;
    }
}
