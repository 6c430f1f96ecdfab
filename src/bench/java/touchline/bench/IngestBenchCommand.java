package touchline.bench;

import touchline.cli.RobotSideBinaries;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.MessageKinds;
import touchline.transport.UdpConfig;

import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Ingest benchmark: the console's UDP pipeline (Netty, framing, decoding, Envelope stream,
 * and without {@code --transport-only} the robot model) against a baseline in the same run, a
 * plain DatagramChannel loop that only parses the protobuf. Both are measured by how fast
 * they drain a filled socket buffer ({@link DrainMeter}; {@code --flood} instead runs
 * {@link BlastSenders} against them), optionally with the recorder attached; then the
 * pipeline's loss at a fixed rate (50 000 messages/s: 40x a team's legal 1 Mbit/s).
 */
@Command(name = "ingest", mixinStandardHelpOptions = true,
        description = "Decoded messages/s of the UDP pipeline vs a plain receive loop, and loss at a fixed rate.")
final class IngestBenchCommand implements Callable<Integer> {

    @Option(names = "--seconds", defaultValue = "5", description = "seconds per measurement (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--rounds", defaultValue = "5", description = "alternating rounds (default ${DEFAULT-VALUE})")
    int rounds;

    @Option(names = "--rate", defaultValue = "50000", description = "fixed rate for the loss test, messages/s (default ${DEFAULT-VALUE})")
    int rate;

    @Option(names = "--transport-only", description = "measure the transport without the model subscribed")
    boolean transportOnly;

    @Option(names = "--compare-recording", description = "each round also runs the pipeline with the recorder attached")
    boolean compareRecording;

    @Option(names = "--flood", description = "measure by flooding from touchline-blast senders while the receiver runs"
            + " (both compete for the two cores) instead of draining a filled socket buffer")
    boolean flood;

    @Option(names = "--tagged", description = "each round also runs the pipeline with a team key, every robot"
            + " datagram carrying its tag (docs/security.md); budget: >= 0.9 of the untagged pipeline")
    boolean tagged;

    @Option(names = "--batch", defaultValue = "3000", description = "drain mode: datagrams per filled buffer (default ${DEFAULT-VALUE})")
    int batch;

    @Option(names = "--senders", defaultValue = "2", description = "touchline-blast processes sending at once: more than"
            + " one, so that the sending side outruns either receiver (default ${DEFAULT-VALUE})")
    int senderCount;

    @Option(names = "--java-sender", description = "saturate with a Java sender thread instead of the C sender touchline-blast")
    boolean javaSender;

    @Option(names = "--threads", description = "drain mode: after each phase, the process's threads that ran most"
            + " (GC and compiler included) and how long each waited for a core, per datagram (Linux schedstat)")
    boolean threads;

    @Option(names = "--compare-shared", description = "each round also runs the pipeline with its two threads free to"
            + " share a core (-Dtouchline.udp.cores=shared), as before the console split them (CoreSplit)")
    boolean compareShared;

    private final IngestTraffic traffic = new IngestTraffic();
    private final List<byte[]> datagrams = traffic.sixRobots(1);
    private BlastSenders blaster;

    /** The C senders, or null (one Java sender thread) when they are not built or not wanted. */
    private void prepareSender() throws java.io.IOException {
        java.nio.file.Path bin = new RobotSideBinaries().of("touchline-blast");
        if (javaSender || !java.nio.file.Files.isExecutable(bin)) {
            System.out.println("sender: one Java thread (DatagramChannel.write)"
                    + (javaSender ? "" : "; touchline-blast not found at " + bin));
            return;
        }
        blaster = new BlastSenders(bin, senderCount, traffic);
        System.out.printf("sender: %d x touchline-blast (C, sendmmsg)%n", senderCount);
    }

    @Override
    public Integer call() throws Exception {
        System.out.printf("ingest benchmark: %d rounds x %d s, %d distinct datagrams (%d..%d bytes), %d cores%n", rounds,
                seconds, datagrams.size(), datagrams.stream().mapToInt(d -> d.length).min().orElse(0),
                datagrams.stream().mapToInt(d -> d.length).max().orElse(0), Runtime.getRuntime().availableProcessors());
        if (flood) {
            prepareSender();
        } else {
            System.out.printf("drain mode: fill the paused receiver's socket buffer with %d datagrams, time how fast it"
                    + " decodes them (the sender idle meanwhile); --flood for senders running against it%n", batch);
        }
        // Warm-up (not counted): the JIT compiles both receive paths before anything is measured.
        // Two warm-up rounds: with ZGC the first full round still ran at half speed.
        for (int w = 0; w < 2; w++) {
            baseline(seconds);
            pipeline(seconds, 0, false, false);
            if (compareRecording) {
                pipeline(seconds, 0, true, false);
            }
            if (tagged) {
                pipeline(seconds, 0, false, true);
            }
        }
        double bestBaseline = 0;
        double bestPipeline = 0;
        List<Double> ratios = new ArrayList<>();
        List<Double> recordingRatios = new ArrayList<>();
        List<Double> taggedRatios = new ArrayList<>();
        List<Double> cpuRatios = new ArrayList<>();
        List<Double> sharedRatios = new ArrayList<>();
        for (int round = 1; round <= rounds; round++) {
            // Every other round measures the tagged pipeline first: the phases run one after the
            // other, so an order effect (the phase before still winding down, the machine drifting)
            // falls on both sides of the tags' ratio instead of always on the tagged one.
            IngestResult tagsFirst = tagged && round % 2 == 0 ? pipeline(seconds, 0, false, true) : null;
            IngestResult base = baseline(seconds);
            double baseline = base.perSecond();
            IngestResult pipe = pipeline(seconds, 0, false, false);
            double pipeline = pipe.perSecond();
            System.out.printf("  (took %.0f%% of what was sent in the baseline, %.0f%% in the pipeline)%n",
                    100.0 * base.received() / base.sent(), 100.0 * pipe.received() / pipe.sent());
            if (compareRecording) {
                IngestResult rec = pipeline(seconds, 0, true, false);
                double recorded = rec.perSecond();
                System.out.printf("round %d: pipeline recording %,.0f msg/s, %.2f of the pipeline without"
                        + " (took %.0f%% of what was sent)%n", round, recorded, recorded / pipeline,
                        100.0 * rec.received() / rec.sent());
                recordingRatios.add(recorded / pipeline);
            }
            if (tagged) {
                IngestResult tags = tagsFirst != null ? tagsFirst : pipeline(seconds, 0, false, true);
                double withTags = tags.perSecond();
                System.out.printf("round %d: pipeline with tags %,.0f msg/s, %.2f of the pipeline without (%s)%n", round,
                        withTags, withTags / pipeline, tagsFirst != null ? "measured first" : "measured last");
                if (!tags.cpuNanosPerMessage().isEmpty()) {
                    System.out.printf("  CPU per datagram with tags: %s%n", tags.cpuText());
                }
                taggedRatios.add(withTags / pipeline);
            }
            if (compareShared) {
                IngestResult shared = withCoresShared(() -> pipeline(seconds, 0, false, false));
                System.out.printf("round %d: pipeline with its threads free to share a core %,.0f msg/s, ratio %.2f%n",
                        round, shared.perSecond(), shared.perSecond() / baseline);
                sharedRatios.add(shared.perSecond() / baseline);
            }
            ratios.add(pipeline / baseline);
            bestBaseline = Math.max(bestBaseline, baseline);
            bestPipeline = Math.max(bestPipeline, pipeline);
            System.out.printf("round %d: baseline %,.0f msg/s, pipeline %,.0f msg/s, ratio %.2f%n", round, baseline,
                    pipeline, pipeline / baseline);
            if (!pipe.cpuNanosPerMessage().isEmpty()) {
                double cpuRatio = base.busiestNanosPerMessage() / pipe.busiestNanosPerMessage();
                cpuRatios.add(cpuRatio);
                System.out.printf("  CPU per datagram: %s | %s; busiest thread's ratio %.2f%n", base.cpuText(),
                        pipe.cpuText(), cpuRatio);
            }
        }
        System.out.printf("best: baseline %,.0f msg/s, pipeline %,.0f msg/s, ratio %.2f; median of the rounds' ratios"
                        + " %.2f (target >= 0.90)%n", bestBaseline, bestPipeline, bestPipeline / bestBaseline, median(ratios));
        if (!cpuRatios.isEmpty()) {
            System.out.printf("CPU: median of the rounds' baseline receiver / busiest pipeline thread, per datagram:"
                    + " %.2f (what two free cores would give; wall-clock figures above count waits for a core)%n",
                    median(cpuRatios));
        }
        if (compareShared) {
            System.out.printf("threads free to share a core: median of the rounds' ratios %.2f%n", median(sharedRatios));
        }
        if (compareRecording) {
            System.out.printf("recording overhead: median %.1f%% over %d rounds (target <= 10%%)%n",
                    100 * (1 - median(recordingRatios)), recordingRatios.size());
        }
        if (tagged) {
            System.out.printf("tags: median %.2f of the untagged pipeline over %d rounds (target >= 0.90)%n",
                    median(taggedRatios), taggedRatios.size());
        }
        IngestResult paced = pipeline(seconds, rate, false, false);
        System.out.printf("fixed rate %,d msg/s for %d s: sent %,d, decoded %,d, lost %,d (%.4f%%)%n", rate, seconds,
                paced.sent(), paced.received(), paced.sent() - paced.received(), 100.0 * (paced.sent() - paced.received()) / paced.sent());
        return 0;
    }

    static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        int n = sorted.size();
        return n == 0 ? Double.NaN : n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }

    private IngestResult pipeline(int secs, int pacedRate, boolean record, boolean withTags) throws Exception {
        System.gc(); // the previous phase's garbage is not collected on this one's time
        DecodedCounter decoded = new DecodedCounter();
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        if (withTags) {
            config = config.withSecurity(touchline.security.LinkSecurity.with(BENCH_KEY,
                    new touchline.security.CounterSource(System::currentTimeMillis,
                            touchline.security.CounterSource.inMemory())));
        }
        try (Console console = transportOnly ? new Console(config, new touchline.app.SystemClock(), false)
                : new Console(config)) {
            console.field().bus().subscribe(e -> {
                if (!e.isMalformed() && e.direction() == touchline.transport.Direction.IN) {
                    decoded.increment();
                }
            });
            java.nio.file.Path file = record ? java.nio.file.Files.createTempFile("touchline-ingest", ".mcap") : null;
            if (record) {
                console.recordings().start(file);
            }
            console.start();
            if (!transportShown) {
                transportShown = true;
                System.out.println("console's transport: " + console.field().transportDescription());
            }
            try {
                if (pacedRate == 0 && !flood) {
                    DrainMeter meter = withTags ? new DrainMeter(this::taggedDatagram, batch) : new DrainMeter(datagrams, batch);
                    IngestResult result = meter.measure(console.field().port(), secs, decoded,
                            () -> console.field().setReading(false), () -> console.field().setReading(true));
                    printThreads(withTags ? "pipeline with tags" : "pipeline", meter);
                    return result;
                }
                return drive(console.field().port(), secs, pacedRate, decoded);
            } finally {
                if (record) {
                    console.recordings().current().ifPresent(s -> System.out.printf("  recorded %,d, dropped %,d%n", s.written(), s.dropped()));
                    console.recordings().stop();
                    java.nio.file.Files.deleteIfExists(file);
                }
            }
        }
    }

    private static IngestResult withCoresShared(Callable<IngestResult> phase) throws Exception {
        System.setProperty(touchline.transport.CoreSplit.PROPERTY, "shared");
        try {
            return phase.call();
        } finally {
            System.clearProperty(touchline.transport.CoreSplit.PROPERTY);
        }
    }

    private boolean transportShown;

    private void printThreads(String phase, DrainMeter meter) {
        if (threads) {
            System.out.printf("  threads, %s: %s%n", phase, meter.threadsText());
        }
    }

    private static final touchline.security.TeamKey BENCH_KEY = new touchline.security.TeamKey(new byte[32]);
    private final touchline.security.MessageTag robotTag = new touchline.security.MessageTag(BENCH_KEY);
    private long robotCounter = 0x0000_1234_0000_0000L;

    /** The n-th datagram as its robot sends it with a team key: the trailer with a fresh counter (sender side, not timed). */
    private byte[] taggedDatagram(long n) {
        int i = (int) (n % datagrams.size());
        return robotTag.append(touchline.security.MessageTag.FROM_ROBOT, 1 + i / 4, ++robotCounter, datagrams.get(i));
    }

    private IngestResult baseline(int secs) throws Exception {
        System.gc(); // the previous phase's garbage is not collected on this one's time
        DecodedCounter decoded = new DecodedCounter();
        AtomicBoolean running = new AtomicBoolean(true);
        MessageKinds kinds = new MessageKinds();
        FrameCodec frames = new FrameCodec();
        // drain mode: the receiver reads until the socket is empty each time it is let go
        java.util.concurrent.Semaphore go = new java.util.concurrent.Semaphore(0);
        java.util.concurrent.Semaphore idle = new java.util.concurrent.Semaphore(0);
        try (DatagramChannel channel = DatagramChannel.open()) {
            channel.setOption(StandardSocketOptions.SO_RCVBUF, UdpConfig.defaults().receiveBuffer());
            channel.bind(new InetSocketAddress("127.0.0.1", 0));
            channel.configureBlocking(flood);
            Thread receiver = new Thread(() -> {
                ByteBuffer buf = ByteBuffer.allocate(2048);
                while (running.get()) {
                    try {
                        if (!flood) {
                            idle.release();
                            go.acquire();
                        }
                        do {
                            buf.clear();
                            if (channel.receive(buf) == null) {
                                break; // drain mode: the socket is empty
                            }
                            byte[] bytes = new byte[buf.position()];
                            buf.flip();
                            buf.get(bytes);
                            var frame = frames.decode(bytes);
                            if (frame instanceof touchline.protocol.FrameResult.Frame f) {
                                Fumanoid.Message.parseFrom(f.payload(), kinds.registry());
                                decoded.increment();
                            }
                        } while (!flood || running.get());
                    } catch (Exception e) {
                        return;
                    }
                }
            }, "baseline-receiver");
            receiver.start();
            int port = ((InetSocketAddress) channel.getLocalAddress()).getPort();
            DrainMeter meter = new DrainMeter(datagrams, batch);
            IngestResult r = flood ? drive(port, secs, 0, decoded)
                    : meter.measure(port, secs, decoded, idle::acquire, go::release);
            if (!flood) {
                printThreads("baseline", meter);
            }
            running.set(false);
            go.release();
            channel.close();
            receiver.join(2000);
            return r;
        }
    }

    /**
     * Sends for {@code secs} seconds (as fast as possible, or at {@code pacedRate}), then waits
     * for the tail. As fast as possible uses the C sender {@code touchline-blast} (sendmmsg)
     * where it is built: one Java sender thread is slower than either receiver, and would
     * measure itself instead of them.
     */
    private IngestResult drive(int port, int secs, int pacedRate, DecodedCounter decoded) throws Exception {
        if (pacedRate == 0 && blaster != null) {
            return blaster.send(port, secs, decoded);
        }
        try (DatagramChannel out = DatagramChannel.open()) {
            out.connect(new InetSocketAddress("127.0.0.1", port));
            ByteBuffer[] buffers = datagrams.stream().map(ByteBuffer::wrap).toArray(ByteBuffer[]::new);
            long start = System.nanoTime();
            long end = start + secs * 1_000_000_000L;
            long sent = 0;
            long startCount = decoded.sum();
            while (System.nanoTime() < end) {
                if (pacedRate > 0) {
                    long due = start + sent * 1_000_000_000L / pacedRate;
                    while (System.nanoTime() < due) {
                        Thread.onSpinWait();
                    }
                }
                ByteBuffer b = buffers[(int) (sent % buffers.length)];
                b.rewind();
                out.write(b);
                sent++;
            }
            long sendEnd = System.nanoTime();
            long received = decoded.awaitSettled() - startCount;
            double elapsed = (sendEnd - start) / 1e9;
            return new IngestResult(sent, received, received / elapsed);
        }
    }
}
