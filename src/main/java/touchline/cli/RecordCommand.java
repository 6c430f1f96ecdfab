package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.protocol.FrameCodec;
import touchline.protocol.FrameResult;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.record.EnvelopeSource;
import touchline.record.EnvelopeWriter;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.record.RecordingException;
import touchline.record.SchemaSet;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.PrintWriter;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.Arrays;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.IntFunction;

/**
 * {@code touchline record}: headless match-day recording of everything the console hears to
 * an MCAP file, until Ctrl+C (or {@code --seconds}). The traffic comes from an
 * {@link EnvelopeSource} per port; the application passes its live transports, and until
 * those are wired in, a plain UDP listener that frames and decodes FUmanoids datagrams.
 */
@Command(name = "record", mixinStandardHelpOptions = true,
        description = "Record every datagram the console receives to an MCAP file (headless).")
public final class RecordCommand implements Callable<Integer> {

    @Option(names = "--out", description = "output file (default: touchline-<date>-<time>.mcap)")
    Path out;

    @Option(names = "--port", defaultValue = "11011", description = "UDP port to listen on (default: ${DEFAULT-VALUE})")
    int port;

    @Option(names = "--split-size", paramLabel = "MB", description = "start a new file after this many megabytes")
    long splitMegabytes;

    @Option(names = "--split-minutes", paramLabel = "N", description = "start a new file every N minutes")
    long splitMinutes;

    @Option(names = "--proto", paramLabel = "FILE",
            description = "a team's protoc descriptor set (.desc/.pb) to embed in the recording")
    Path proto;

    @Option(names = "--seconds", description = "stop after this many seconds (default: until Ctrl+C)")
    long seconds;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    private final IntFunction<EnvelopeSource> sources;

    public RecordCommand() {
        this(UdpSource::new);
    }

    /** {@code sources} gives the live traffic source for a port (the application's transports). */
    public RecordCommand(IntFunction<EnvelopeSource> sources) {
        this.sources = sources;
    }

    @Override
    public Integer call() throws Exception {
        PrintWriter err = spec.commandLine().getErr();
        PrintWriter stdout = spec.commandLine().getOut();
        Path file = out != null ? out
                : Path.of("touchline-" + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd-HHmmss")) + ".mcap");
        EnvelopeWriter.Options options = EnvelopeWriter.Options.defaults()
                .withSplit(splitMegabytes * 1_000_000L, splitMinutes * 60_000_000L);
        if (proto != null) {
            try {
                SchemaSet schemas = new SchemaSet();
                schemas.load(proto);
                options = options.withTeamFiles(schemas.teamFiles());
            } catch (RecordingException e) {
                err.println("touchline record: " + e.getMessage());
                return 2;
            }
        }
        Recorder recorder = new Recorder(file, options);
        CountDownLatch stop = new CountDownLatch(1);
        Thread hook = new Thread(stop::countDown, "touchline-record-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        AutoCloseable source;
        try {
            source = sources.apply(port).start(recorder);
        } catch (Exception e) {
            recorder.close();
            err.println("touchline record: cannot listen on port " + port + ": " + e.getMessage());
            return 1;
        }
        stdout.println("recording port " + port + " to " + file.toAbsolutePath() + " (Ctrl+C to stop)");
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
        source.close();
        recorder.close();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // Ctrl+C: the JVM is exiting anyway, and the file is finished above
        }
        RecorderStats s = recorder.stats();
        stdout.printf("recorded %d envelopes (%d dropped) to %s%n", s.written(), s.dropped(), s.files());
        stdout.flush();
        return s.failure() == null ? 0 : 1;
    }

    /**
     * Stand-in until the application's UDP transport is wired in: receives datagrams on a port
     * and publishes them as Envelopes (FUmanoids framed and decoded, GameController packets and
     * reliable-stream segments raw, bad datagrams with their reason).
     */
    static final class UdpSource implements EnvelopeSource {
        private final int port;

        UdpSource(int port) {
            this.port = port;
        }

        @Override
        public AutoCloseable start(EnvelopeSink sink) throws SocketException {
            DatagramSocket socket = new DatagramSocket(port);
            FrameCodec frames = new FrameCodec();
            MessageCodec codec = new MessageCodec(new MessageKinds());
            Thread t = new Thread(() -> {
                byte[] buf = new byte[65536];
                DatagramPacket p = new DatagramPacket(buf, buf.length);
                while (!socket.isClosed()) {
                    try {
                        socket.receive(p);
                    } catch (java.io.IOException e) {
                        return;
                    }
                    long now = System.currentTimeMillis() * 1000L;
                    byte[] raw = Arrays.copyOf(buf, p.getLength());
                    sink.accept(envelope(now, (InetSocketAddress) p.getSocketAddress(), raw, frames, codec));
                }
            }, "touchline-record-udp");
            t.setDaemon(true);
            t.start();
            return socket::close;
        }

        static Envelope envelope(long now, InetSocketAddress peer, byte[] raw, FrameCodec frames, MessageCodec codec) {
            if (raw.length >= 2 && raw[0] == 'R' && raw[1] == 'G') {
                return new Envelope(now, Direction.IN, Channel.GAMECONTROLLER, peer, Envelope.NO_ROBOT, "gamecontroller",
                        null, raw, null);
            }
            if (raw.length >= 2 && raw[0] < 42 && raw[1] < 42 && raw[0] >= 0 && raw[1] >= 0 && !(raw[0] == 0 && raw[1] == 42)
                    && frames.decode(raw) instanceof FrameResult.Malformed) {
                return new Envelope(now, Direction.IN, Channel.RELIABLE_STREAM, peer, Envelope.NO_ROBOT, "segment",
                        null, raw, null);
            }
            FrameResult frame = frames.decode(raw);
            if (frame instanceof FrameResult.Malformed m) {
                return new Envelope(now, Direction.IN, Channel.FUMANOID, peer, Envelope.NO_ROBOT, "malformed", null, raw,
                        m.reason());
            }
            MessageResult result = codec.decode(((FrameResult.Frame) frame).payload());
            if (result instanceof MessageResult.Decoded d) {
                return new Envelope(now, Direction.IN, Channel.FUMANOID, peer, d.message().getRobotID(), d.kind(),
                        d.message(), raw, null);
            }
            return new Envelope(now, Direction.IN, Channel.FUMANOID, peer, Envelope.NO_ROBOT, "malformed", null, raw,
                    ((MessageResult.Malformed) result).reason());
        }
    }

    public static void main(String[] args) {
        System.exit(new CommandLine(new RecordCommand()).execute(args));
    }
}
