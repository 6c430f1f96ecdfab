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
 * (so the machine's load does not count): the ingest benchmark's datagrams are copied, framed,
 * decoded into envelopes as the transport does (loop "decode"), and in the other loop
 * ("decode + model") also handed to every subscriber of a real console's bus in turn (robot
 * registry, traffic meter, option session, the views' stores, match mode's game-state feed).
 * The difference is the model's cost per envelope, the work {@code touchline-decode} does
 * beside the event loop. The console is built but not started: no socket, no tick.
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
    private long sink;

    @Override
    public Integer call() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config, () -> nowMicros)) {
            for (int w = 0; w < 3; w++) {
                loop(console, false);
                loop(console, true);
            }
            List<Double> decode = new ArrayList<>();
            List<Double> model = new ArrayList<>();
            List<Double> both = new ArrayList<>();
            for (int r = 1; r <= rounds; r++) {
                double d = loop(console, false);
                double all = loop(console, true);
                decode.add(d);
                both.add(all);
                model.add(all - d);
                System.out.printf("round %d: decode %.0f ns, decode + model %.0f ns, model %.0f ns per envelope%n",
                        r, d, all, all - d);
            }
            System.out.printf("median over %d rounds: decode %.0f ns, model subscribers %.0f ns per envelope"
                    + " (CPU time of this thread; %d subscriber failures)%n", rounds, median(decode), median(model),
                    console.bus().subscriberFailures());
            // a shared machine only ever adds (time stolen from a virtual CPU counts as the thread's)
            System.out.printf("fastest rounds: decode %.0f ns, decode + model %.0f ns: model %.0f ns per envelope%n",
                    Collections.min(decode), Collections.min(both), Collections.min(both) - Collections.min(decode));
        }
        return sink == 42 ? 1 : 0;
    }

    /** CPU nanoseconds per envelope of one loop. */
    private double loop(Console console, boolean publish) throws Exception {
        InetAddress host = InetAddress.getLoopbackAddress();
        long start = mx.getCurrentThreadCpuTime();
        for (int n = 0; n < envelopes; n++) {
            int i = n % datagrams.size();
            byte[] bytes = Arrays.copyOf(datagrams.get(i), datagrams.get(i).length);
            nowMicros += 20;
            Envelope e = envelope(bytes, new InetSocketAddress(host, 20_000 + i / 4));
            if (publish) {
                console.bus().accept(e);
            } else {
                sink += e.kind().length();
            }
        }
        return (mx.getCurrentThreadCpuTime() - start) / (double) envelopes;
    }

    private Envelope envelope(byte[] bytes, InetSocketAddress peer) {
        FrameResult.Frame f = (FrameResult.Frame) frames.decode(bytes);
        MessageResult.Decoded d = (MessageResult.Decoded) messages.decode(f.payload());
        return new Envelope(nowMicros, Direction.IN, Channel.FUMANOID, peer, d.message().getRobotID(), d.kind(),
                d.message(), bytes, null);
    }

    private static double median(List<Double> values) {
        List<Double> sorted = values.stream().sorted().toList();
        int n = sorted.size();
        return n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
    }
}
