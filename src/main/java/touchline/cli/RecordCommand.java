package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.LiveField;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.record.RecordingException;

import java.io.PrintWriter;
import java.io.IOException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import java.util.function.Function;
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

    private final Function<ConsoleConfig, Console> consoles;
    private final Consumer<LiveField> started;

    /** Records what the application core ({@link Console}: UDP transport and model) sees. */
    public RecordCommand() {
        this(Console::new, field -> { });
    }

    /**
     * {@code consoles} makes the console for a configuration (tests: one without a model);
     * {@code started} is told once it records and listens (tests feed it envelopes there).
     */
    RecordCommand(Function<ConsoleConfig, Console> consoles, Consumer<LiveField> started) {
        this.consoles = consoles;
        this.started = started;
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
        Console console;
        try {
            console = consoles.apply(udp.config());
        } catch (Exception e) {
            err.println("touchline record: cannot listen on port " + udp.port + ": " + e.getMessage());
            return 1;
        }
        Recorder recorder;
        try {
            if (proto != null) {
                console.teamSchemas().load(proto);
                options = options.withTeamFiles(console.teamSchemas().teamFiles());
            }
            recorder = console.recordings().start(file, options);
        } catch (RecordingException e) {
            console.close();
            err.println("touchline record: " + e.getMessage());
            return 2;
        } catch (IOException | RuntimeException e) {
            console.close();
            throw e;
        }
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
            return record(file, console, recorder, stop, hook, stdout, err);
        } finally {
            finished.countDown();
        }
    }

    private int record(Path file, Console console, Recorder recorder, CountDownLatch stop, Thread hook,
                       PrintWriter stdout, PrintWriter err) throws Exception {
        try {
            console.start();
        } catch (Exception e) {
            console.close();
            err.println("touchline record: cannot listen on port " + udp.port + ": " + e.getMessage());
            return 1;
        }
        started.accept(console.field());
        int port = console.field().port();
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
        console.close(); // the recording is finished (summary, footer) before the console stops listening
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
