package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
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
 * robot model) against a baseline in the same run, a plain DatagramChannel loop that only
 * parses the protobuf. Reports the best-effort throughput of both and the loss of the
 * pipeline at a fixed rate (50 000 messages/s: 40x a team's legal 1 Mbit/s).
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

    @Option(names = "--batch", defaultValue = "3000", description = "drain mode: datagrams per filled buffer (default ${DEFAULT-VALUE})")
    int batch;

    @Option(names = "--senders", defaultValue = "2", description = "touchline-blast processes sending at once: more than"
            + " one, so that the sending side outruns either receiver (default ${DEFAULT-VALUE})")
    int senderCount;

    @Option(names = "--java-sender", description = "saturate with a Java sender thread instead of the C sender touchline-blast")
    boolean javaSender;

    private final List<byte[]> datagrams = sampleTraffic(1);
    private java.nio.file.Path blaster;
    /** One file per sender: each sender is its own six robots, as on a field (a robot keeps its address). */
    private final List<java.nio.file.Path> datagramFiles = new ArrayList<>();

    /** The C sender and the file of datagrams it sends, or null (Java sender) when it is not built. */
    private void prepareSender() throws java.io.IOException {
        java.nio.file.Path bin = java.nio.file.Path.of(System.getProperty("touchline.robotside.bin", "robot-side/build/bin"))
                .resolve("touchline-blast");
        if (javaSender || !java.nio.file.Files.isExecutable(bin)) {
            System.out.println("sender: one Java thread (DatagramChannel.write)"
                    + (javaSender ? "" : "; touchline-blast not found at " + bin));
            return;
        }
        for (int i = 0; i < senderCount; i++) {
            java.nio.file.Path file = java.nio.file.Files.createTempFile("touchline-ingest", ".bin");
            file.toFile().deleteOnExit();
            try (java.io.DataOutputStream out = new java.io.DataOutputStream(java.nio.file.Files.newOutputStream(file))) {
                for (byte[] d : sampleTraffic(1 + 6 * i)) {
                    out.writeShort(d.length);
                    out.write(d);
                }
            }
            datagramFiles.add(file);
        }
        blaster = bin;
        System.out.printf("sender: %d x touchline-blast (C, sendmmsg)%n", senderCount);
    }

    private Result blast(int port, int secs, Decoded decoded) throws Exception {
        long startCount = decoded.sum();
        List<Process> senders = new ArrayList<>();
        for (java.nio.file.Path file : datagramFiles) {
            senders.add(new ProcessBuilder(blaster.toString(), "--to", "127.0.0.1:" + port, "--file",
                    file.toString(), "--seconds", Integer.toString(secs))
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start());
        }
        long sent = 0;
        double elapsed = 0;
        for (Process p : senders) {
            String line = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.US_ASCII).trim();
            if (p.waitFor() != 0 || !line.startsWith("sent ")) {
                throw new IllegalStateException("touchline-blast failed: " + line);
            }
            String[] words = line.split(" ");
            sent += Long.parseLong(words[1]);
            elapsed = Math.max(elapsed, Double.parseDouble(words[3]));
        }
        long last = -1;
        while (decoded.sum() != last) { // wait until the receiver has drained its socket buffer
            last = decoded.sum();
            Thread.sleep(200);
        }
        long received = decoded.sum() - startCount;
        return new Result(sent, received, received / elapsed);
    }

    /** Six robots' realistic mix (IDs from {@code firstRobot}): keep-alives, plots, text, region growing. */
    static List<byte[]> sampleTraffic(int firstRobot) {
        FrameCodec frames = new FrameCodec();
        List<byte[]> out = new ArrayList<>();
        for (int robot = firstRobot; robot < firstRobot + 6; robot++) {
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTimestamp(123456789L).setTeamID(13)
                            .setTimeOnline(42).setActiveRole("striker").setCurrentState("walking").setRobotName("fu" + robot)
                            .setBatteryPercent(80).setRobotPosition(Fumanoid.Position.newBuilder().setX(1200).setY(-300).setTheta(0.5f))
                            .build()).build().toByteArray()));
            Fumanoid.DebugPlot.Builder plot = Fumanoid.DebugPlot.newBuilder().setOption("demo.plotter").setTimestamp(1);
            for (int s = 0; s < 4; s++) {
                plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeries("series" + s).setValue(s * 0.5));
            }
            out.add(frames.encode(Framing.LENGTH_PREFIX, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.debugPlot, plot.build()).build().toByteArray()));
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("demo.text")
                            .setText("ball seen at 1.2 m, bearing 12 deg").build()).build().toByteArray()));
            Fumanoid.RegionGrowing.Builder regions = Fumanoid.RegionGrowing.newBuilder().setOption("havimo.region")
                    .setFrameWidth(160).setFrameHeight(120);
            for (int r = 0; r < 5; r++) {
                regions.addRegions(Fumanoid.Region.newBuilder().setColorClass(r).setX1(r * 10).setY1(r * 5).setX2(r * 10 + 20).setY2(r * 5 + 12));
            }
            out.add(frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(robot)
                    .setExtension(Fumanoid.regionGrowing, regions.build()).build().toByteArray()));
        }
        return out;
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
            pipeline(seconds, 0, false);
            if (compareRecording) {
                pipeline(seconds, 0, true);
            }
        }
        double bestBaseline = 0;
        double bestPipeline = 0;
        List<Double> ratios = new ArrayList<>();
        List<Double> recordingRatios = new ArrayList<>();
        for (int round = 1; round <= rounds; round++) {
            Result base = baseline(seconds);
            double baseline = base.perSecond;
            Result pipe = pipeline(seconds, 0, false);
            double pipeline = pipe.perSecond;
            System.out.printf("  (took %.0f%% of what was sent in the baseline, %.0f%% in the pipeline)%n",
                    100.0 * base.received / base.sent, 100.0 * pipe.received / pipe.sent);
            if (compareRecording) {
                Result rec = pipeline(seconds, 0, true);
                double recorded = rec.perSecond;
                System.out.printf("round %d: pipeline recording %,.0f msg/s, %.2f of the pipeline without"
                        + " (took %.0f%% of what was sent)%n", round, recorded, recorded / pipeline,
                        100.0 * rec.received / rec.sent);
                recordingRatios.add(recorded / pipeline);
            }
            ratios.add(pipeline / baseline);
            bestBaseline = Math.max(bestBaseline, baseline);
            bestPipeline = Math.max(bestPipeline, pipeline);
            System.out.printf("round %d: baseline %,.0f msg/s, pipeline %,.0f msg/s, ratio %.2f%n", round, baseline,
                    pipeline, pipeline / baseline);
        }
        System.out.printf("best: baseline %,.0f msg/s, pipeline %,.0f msg/s, ratio %.2f; median of the rounds' ratios"
                        + " %.2f (target >= 0.80)%n", bestBaseline, bestPipeline, bestPipeline / bestBaseline, median(ratios));
        if (compareRecording) {
            System.out.printf("recording overhead: median %.1f%% over %d rounds (target <= 10%%)%n",
                    100 * (1 - median(recordingRatios)), recordingRatios.size());
        }
        Result paced = pipeline(seconds, rate, false);
        System.out.printf("fixed rate %,d msg/s for %d s: sent %,d, decoded %,d, lost %,d (%.4f%%)%n", rate, seconds,
                paced.sent, paced.received, paced.sent - paced.received, 100.0 * (paced.sent - paced.received) / paced.sent);
        return 0;
    }

    private record Result(long sent, long received, double perSecond) { }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        int n = sorted.size();
        return n == 0 ? Double.NaN : n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }

    private Result pipeline(int secs, int pacedRate, boolean record) throws Exception {
        System.gc(); // the previous phase's garbage is not collected on this one's time
        Decoded decoded = new Decoded();
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = transportOnly ? new Console(config, touchline.transport.MicrosClock.system(), false)
                : new Console(config)) {
            console.bus().subscribe(e -> {
                if (!e.isMalformed() && e.direction() == touchline.transport.Direction.IN) {
                    decoded.increment();
                }
            });
            java.nio.file.Path file = record ? java.nio.file.Files.createTempFile("touchline-ingest", ".mcap") : null;
            if (record) {
                console.startRecording(file);
            }
            console.start();
            try {
                if (pacedRate == 0 && !flood) {
                    return drain(console.udp().localPort(), secs, decoded, new Reading() {
                        @Override
                        public void pause() throws InterruptedException {
                            console.udp().setReading(false);
                        }

                        @Override
                        public void resume() throws InterruptedException {
                            console.udp().setReading(true);
                        }
                    });
                }
                return drive(console.udp().localPort(), secs, pacedRate, decoded);
            } finally {
                if (record) {
                    console.recording().ifPresent(s -> System.out.printf("  recorded %,d, dropped %,d%n", s.written(), s.dropped()));
                    console.stopRecording();
                    java.nio.file.Files.deleteIfExists(file);
                }
            }
        }
    }

    /**
     * Messages decoded, counted by the receiving thread; in drain mode it also notes when the
     * expected count was reached and wakes the waiting benchmark thread.
     */
    static final class Decoded {
        private final java.util.concurrent.atomic.AtomicLong count = new java.util.concurrent.atomic.AtomicLong();
        private volatile long expected = Long.MAX_VALUE;
        private volatile long reachedNanos;
        private volatile Thread waiter;

        void increment() {
            if (count.incrementAndGet() == expected) {
                reachedNanos = System.nanoTime();
                java.util.concurrent.locks.LockSupport.unpark(waiter);
            }
        }

        long sum() {
            return count.get();
        }

        void expect(long total) {
            waiter = Thread.currentThread();
            reachedNanos = 0;
            expected = total;
        }

        /** When the expected count was reached, or the time given up at the deadline. */
        long await(long deadlineNanos) {
            long now;
            while (count.get() < expected && (now = System.nanoTime()) < deadlineNanos) {
                java.util.concurrent.locks.LockSupport.parkNanos(this, deadlineNanos - now);
            }
            long reached = reachedNanos;
            expected = Long.MAX_VALUE;
            return reached != 0 ? reached : System.nanoTime();
        }
    }

    /** How a receiver is held while its socket buffer is filled, and let go. */
    private interface Reading {
        void pause() throws InterruptedException;

        void resume() throws InterruptedException;
    }

    /**
     * Drain mode: with the receiver paused, fill its socket buffer with {@link #batch}
     * datagrams, let it go and time until it has decoded them all; repeated for {@code secs}
     * seconds. Rate = datagrams decoded / time spent draining. The sender is idle while the
     * receiver works, so on two cores the figure is the receiver's own capacity, not a share
     * of a core it fights the sender for. A batch the kernel did not take whole (buffer full)
     * is left out and the batch made smaller.
     */
    private Result drain(int port, int secs, Decoded decoded, Reading reading) throws Exception {
        try (DatagramChannel out = DatagramChannel.open()) {
            out.connect(new InetSocketAddress("127.0.0.1", port));
            ByteBuffer[] buffers = datagrams.stream().map(ByteBuffer::wrap).toArray(ByteBuffer[]::new);
            reading.pause();
            long end = System.nanoTime() + secs * 1_000_000_000L;
            long sent = 0;
            long received = 0;
            long drainingNanos = 0;
            int size = batch;
            int incomplete = 0;
            while (System.nanoTime() < end) {
                long before = decoded.sum();
                for (int i = 0; i < size; i++) {
                    ByteBuffer b = buffers[(int) (sent % buffers.length)];
                    b.rewind();
                    out.write(b);
                    sent++;
                }
                if (decoded.sum() != before) {
                    throw new IllegalStateException("the receiver read while paused");
                }
                decoded.expect(before + size);
                long t0 = System.nanoTime();
                reading.resume();
                // parked, not spinning: the second core stays free for the receiver's own threads
                long t1 = decoded.await(t0 + 1_000_000_000L);
                reading.pause();
                long got = decoded.sum() - before;
                if (got < size) {
                    incomplete++;
                    size = Math.max(100, size * 3 / 4);
                    continue;
                }
                drainingNanos += t1 - t0;
                received += got;
            }
            reading.resume();
            if (incomplete > 0) {
                System.out.printf("  (%d batches not taken whole by the kernel, left out; batch now %d)%n", incomplete, size);
            }
            return new Result(received, received, received / (drainingNanos / 1e9));
        }
    }

    private Result baseline(int secs) throws Exception {
        System.gc(); // the previous phase's garbage is not collected on this one's time
        Decoded decoded = new Decoded();
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
            Result r = flood ? drive(port, secs, 0, decoded) : drain(port, secs, decoded, new Reading() {
                @Override
                public void pause() throws InterruptedException {
                    idle.acquire();
                }

                @Override
                public void resume() {
                    go.release();
                }
            });
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
    private Result drive(int port, int secs, int pacedRate, Decoded decoded) throws Exception {
        if (pacedRate == 0 && blaster != null) {
            return blast(port, secs, decoded);
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
            long last = -1;
            while (decoded.sum() != last) { // wait until the receiver has drained its socket buffer
                last = decoded.sum();
                Thread.sleep(200);
            }
            long received = decoded.sum() - startCount;
            double elapsed = (sendEnd - start) / 1e9;
            return new Result(sent, received, received / elapsed);
        }
    }
}
