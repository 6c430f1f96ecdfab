package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import com.google.protobuf.Descriptors.FileDescriptor;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeSource;
import touchline.record.EnvelopeWriter;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.record.RecordingException;
import touchline.record.SchemaSet;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.BiFunction;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * {@code touchline record}: headless match-day recording of everything the console hears and
 * sends to an MCAP file, until Ctrl+C, SIGTERM (or {@code --seconds}). The traffic is the
 * application core's Envelope stream ({@link Console}, as {@code listen} runs it), so the
 * robots are greeted and asked for their options exactly as in the console. However the
 * recording ends, the file is finished (data end, summary, footer) and the summary printed
 * before the process exits: a signal's shutdown hook waits until that is done.
 */
@Command(name = "record", mixinStandardHelpOptions = true,
        description = "Record every datagram the console receives to an MCAP file (headless).")
public final class RecordCommand implements Callable<Integer> {

    @Option(names = "--out", description = "output file (default: touchline-<date>-<time>.mcap)")
    Path out;

    @CommandLine.Mixin
    UdpOptions udp;

    @Option(names = "--split-size", paramLabel = "MB", description = "start a new file after this many megabytes")
    long splitMegabytes;

    @Option(names = "--split-minutes", paramLabel = "N", description = "start a new file every N minutes")
    long splitMinutes;

    @Option(names = "--proto", paramLabel = "FILE",
            description = "a team's protoc descriptor set (.desc/.pb) to embed in the recording")
    Path proto;

    @Option(names = "--camera-fps", paramLabel = "N", description = "record at most N camera frames a second per camera (default: all)")
    double cameraFps;

    @Option(names = "--seconds", description = "stop after this many seconds (default: until Ctrl+C)")
    long seconds;

    @Option(names = "--compression", paramLabel = "none|zstd|lz4", defaultValue = "none",
            converter = CompressionOption.class,
            description = "compression of the file's chunks (default: ${DEFAULT-VALUE})")
    ChunkCompression compression;

    /** How long a signal waits for the file to be finished before the JVM exits regardless. */
    private static final long FINISH_TIMEOUT_SECONDS = 20;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    private final BiFunction<ConsoleConfig, List<FileDescriptor>, EnvelopeSource> sources;

    /** Records what the application core ({@link Console}: UDP transport and model) sees. */
    public RecordCommand() {
        this((config, teamFiles) -> sink -> {
            Console console = new Console(config);
            console.loadTeamSchemas(teamFiles);
            console.bus().subscribe(sink);
            return console.start();
        });
    }

    /** {@code sources} gives the live traffic for a configuration and the team's own types (tests pass a fake). */
    public RecordCommand(BiFunction<ConsoleConfig, List<FileDescriptor>, EnvelopeSource> sources) {
        this.sources = sources;
    }

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        // The real clock, made here once: the file is named before the console (which has its own) exists.
        Path file = out != null ? out
                : Path.of("touchline-" + LocalDateTime.ofInstant(new touchline.app.SystemClock().instant(), java.time.ZoneId.systemDefault()).format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")) + ".mcap");
        EnvelopeWriter.Options options = EnvelopeWriter.Options.defaults().withCompression(compression)
                .withSplit(splitMegabytes * 1_000_000L, splitMinutes * 60_000_000L).withCameraRate(cameraFps);
        List<FileDescriptor> teamFiles = List.of();
        if (proto != null) {
            try {
                SchemaSet schemas = new SchemaSet();
                schemas.load(proto);
                teamFiles = schemas.teamFiles();
                options = options.withTeamFiles(teamFiles);
            } catch (RecordingException e) {
                err.println("touchline record: " + e.getMessage());
                return 2;
            }
        }
        Recorder recorder = new Recorder(file, options);
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch finished = new CountDownLatch(1);
        // The JVM exits as soon as its shutdown hooks return, killing the thread that writes
        // the summary: so the hook asks the recording to end and waits until the file is finished
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                finished.await(FINISH_TIMEOUT_SECONDS, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "touchline-record-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        try {
            return record(file, options, teamFiles, recorder, stop, hook, stdout, err);
        } finally {
            finished.countDown();
        }
    }

    private int record(Path file, EnvelopeWriter.Options options, List<FileDescriptor> teamFiles, Recorder recorder,
                       CountDownLatch stop, Thread hook, PrintWriter stdout, PrintWriter err) throws Exception {
        AutoCloseable source;
        try {
            source = sources.apply(udp.config(), teamFiles).start(recorder);
        } catch (Exception e) {
            recorder.close();
            err.println("touchline record: cannot listen on port " + udp.port + ": " + e.getMessage());
            return 1;
        }
        int port = source instanceof Console c ? c.port() : udp.port;
        stdout.println("recording UDP port " + port + " to " + file.toAbsolutePath() + " (Ctrl+C to stop)");
        stdout.flush();
        long deadline = seconds > 0 ? System.nanoTime() + seconds * 1_000_000_000L : Long.MAX_VALUE;
        while (!stop.await(Math.min(5_000_000_000L, Math.max(1, deadline - System.nanoTime())), TimeUnit.NANOSECONDS)) {
            RecorderStats s = recorder.stats();
            stdout.printf("%d envelopes, %.1f MB, %d dropped%s%n", s.written(), s.bytes() / 1e6, s.dropped(),
                    s.failure() == null ? "" : " — " + s.failure());
            stdout.flush();
            if (System.nanoTime() >= deadline) {
                break;
            }
        }
        try {
            source.close();
        } finally {
            recorder.close();
        }
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // Ctrl+C: the JVM is exiting anyway, and the file is finished above
        }
        RecorderStats s = recorder.stats();
        stdout.printf("recorded %d envelopes (%d dropped) to %s%s%n", s.written(), s.dropped(), s.files(),
                stop.getCount() != 0 ? "" : s.failure() == null ? " (stopped by a signal; the file is finished)"
                        : " (stopped by a signal)");
        if (s.failure() != null) {
            // e.g. a full disk: there was no room for the summary, so say how to get a finished file
            stdout.printf("%s; the file is not finished: 'touchline recover %s' writes a finished copy of what it"
                    + " holds%n", s.failure(), s.files().get(s.files().size() - 1));
        }
        stdout.flush();
        return s.failure() == null ? 0 : 1;
    }

}
