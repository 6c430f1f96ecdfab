package touchline.bench;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.protocol.FrameCodec;
import touchline.protocol.FrameResult;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.Callable;

/**
 * What the model's subscribers cost per envelope, on one thread and by that thread's CPU time
 * (so the machine's load does not count): the ingest benchmark's datagrams are copied, framed
 * and decoded into envelopes as the transport does, 32 at a time (a socket read's batch), and
 * each batch is then handed to every subscriber of a real console's bus in turn (robot registry,
 * traffic meter, option session, the views' stores, match mode's game-state feed), both timed
 * apart. The model's share is the work {@code touchline-decode} does beside the event loop.
 * The console is built but not started: no socket, no tick.
 */
@Command(name = "subscribers", mixinStandardHelpOptions = true,
        description = "CPU ns per envelope of the model's subscribers (one thread, no socket).")
final class SubscriberCostBench implements Callable<Integer> {

    @Option(names = "--envelopes", defaultValue = "200000", description = "envelopes per loop (default ${DEFAULT-VALUE})")
    int envelopes;

    @Option(names = "--rounds", defaultValue = "15", description = "rounds of both loops after warm-up (default ${DEFAULT-VALUE})")
    int rounds;

    private final List<byte[]> datagrams = new IngestTraffic().sixRobots(1);
    private final FrameCodec frames = new FrameCodec();
    private final MessageCodec messages = new MessageCodec(new MessageKinds());
    private final ThreadMXBean mx = ManagementFactory.getThreadMXBean();
    /** The receive time of the next envelope: 50 000 a second, as the loss test sends. */
    private long nowMicros = 1_700_000_000_000_000L;
    /** Envelopes decoded before they are published: a socket read's worth, as the transport hands them over. */
    private static final int BATCH = 32;

    @Override
    public Integer call() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config, () -> nowMicros)) {
            for (int w = 0; w < 5; w++) {
                round(console);
            }
            List<Double> decode = new ArrayList<>();
            List<Double> model = new ArrayList<>();
            for (int r = 1; r <= rounds; r++) {
                double[] cost = round(console);
                decode.add(cost[0]);
                model.add(cost[1]);
                System.out.printf("round %d: decode %.0f ns, model %.0f ns per envelope%n", r, cost[0], cost[1]);
            }
            // a shared machine only ever adds (time stolen from a virtual CPU counts as the thread's)
            System.out.printf("over %d rounds: decode median %.0f ns (fastest %.0f), model subscribers median %.0f ns"
                            + " (fastest %.0f) per envelope, CPU time of this thread; %d subscriber failures%n", rounds,
                    IngestBenchCommand.median(decode), Collections.min(decode), IngestBenchCommand.median(model), Collections.min(model),
                    console.field().bus().subscriberFailures());
        }
        return 0;
    }

    /**
     * One round: {@link #envelopes} datagrams decoded into envelopes a batch at a time, each batch
     * then handed to the bus; the two timed apart. Returns CPU ns per envelope {decode, model}.
     */
    private double[] round(Console console) {
        InetAddress host = InetAddress.getLoopbackAddress();
        Envelope[] batch = new Envelope[BATCH];
        long decodeNanos = 0;
        long modelNanos = 0;
        for (int done = 0; done < envelopes; done += BATCH) {
            long t0 = mx.getCurrentThreadCpuTime();
            for (int k = 0; k < BATCH; k++) {
                int i = (done + k) % datagrams.size();
                byte[] bytes = Arrays.copyOf(datagrams.get(i), datagrams.get(i).length);
                nowMicros += 20;
                batch[k] = envelope(bytes, new InetSocketAddress(host, 20_000 + i / 4));
            }
            long t1 = mx.getCurrentThreadCpuTime();
            for (Envelope e : batch) {
                console.field().bus().accept(e);
            }
            long t2 = mx.getCurrentThreadCpuTime();
            decodeNanos += t1 - t0;
            modelNanos += t2 - t1;
        }
        int n = (envelopes / BATCH) * BATCH + (envelopes % BATCH == 0 ? 0 : BATCH);
        return new double[] {decodeNanos / (double) n, modelNanos / (double) n};
    }

    private Envelope envelope(byte[] bytes, InetSocketAddress peer) {
        FrameResult.Frame f = (FrameResult.Frame) frames.decode(bytes);
        MessageResult.Decoded d = (MessageResult.Decoded) messages.decode(f.payload());
        return new Envelope(nowMicros, Direction.IN, Channel.FUMANOID, peer, d.message().getRobotID(), d.kind(),
                d.message(), bytes, null);
    }
}
