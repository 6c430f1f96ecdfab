package touchline.bench.serve;

import picocli.CommandLine;
import touchline.protocol.MessageKinds;
import touchline.bench.record.SyntheticTeam;
import touchline.serve.FoxgloveServer;
import touchline.serve.ServeConfig;
import touchline.serve.ServeStats;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeBus;
import touchline.transport.MicrosClock;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.concurrent.locks.LockSupport;

/**
 * What serving costs the ingest, at the UI benchmark's load (a six-robot team, 2 400
 * envelopes/s): the publishing (network) thread's rate and CPU time per envelope with the live
 * server attached and no viewers, against the same with {@code --viewers} viewers subscribed to
 * every channel (one of them stalled with {@code --stalled}), alternating rounds in one run; and
 * each viewer's latency from publishing to receiving the frame (p50/p99). Viewers run in this
 * JVM on the same cores, so the figures are an upper bound for viewers on other machines.
 */
@CommandLine.Command(name = "serve", mixinStandardHelpOptions = true,
        description = "Ingest rate, CPU per envelope and viewer latency with viewers subscribed to everything vs none.")
public final class ServeBenchmark implements Callable<Integer> {

    @CommandLine.Option(names = "--viewers", defaultValue = "8", description = "viewers subscribed to everything (default ${DEFAULT-VALUE})")
    int viewerCount;

    @CommandLine.Option(names = "--rate", defaultValue = "2400", description = "envelopes/s published (default ${DEFAULT-VALUE}: the UI benchmark's load)")
    int rate;

    @CommandLine.Option(names = "--seconds", defaultValue = "5", description = "seconds per measurement (default ${DEFAULT-VALUE})")
    int seconds;

    @CommandLine.Option(names = "--rounds", defaultValue = "3", description = "alternating rounds (default ${DEFAULT-VALUE})")
    int rounds;

    @CommandLine.Option(names = "--stalled", description = "one of the viewers stops reading")
    boolean stalled;

    @CommandLine.Option(names = "--udp", description = "the whole console instead of a bare bus: the team's datagrams "
            + "sent over loopback UDP to a started Console (model, stores) with the server subscribed as touchline serve "
            + "does; latency is from the datagram's receive time stamp to the frame")
    boolean udp;

    private final MicrosClock clock = new touchline.app.SystemClock();
    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();

    /** Envelopes/s achieved and CPU nanoseconds per envelope of the publishing thread. */
    private record Ingest(double rate, double cpuNanos) {
    }

    @Override
    public Integer call() throws Exception {
        List<Envelope> team = new ArrayList<>();
        new SyntheticTeam(6, clock.nowMicros(), 5).generate(60, team::add);
        team.removeIf(e -> e.message() == null);
        if (udp) {
            return new UdpServeRun(clock, team, rate, seconds, rounds, viewerCount, stalled).call();
        }
        System.out.printf(Locale.ROOT, "serve benchmark: %d rounds x %d s at %d envelopes/s (%d envelopes of a six-robot "
                + "team cycled), %d viewers%s%n", rounds, seconds, rate, team.size(), viewerCount, stalled ? " (one stalled)" : "");
        EnvelopeBus bus = new EnvelopeBus();
        try (FoxgloveServer server = new FoxgloveServer(ServeConfig.defaults().withPort(0), new MessageKinds(), clock).start()) {
            bus.subscribe(server);
            for (Envelope e : team) {
                bus.accept(e); // every channel exists before the viewers come
            }
            for (int r = 0; r < rounds; r++) {
                RoundConditions quiet = new RoundConditions();
                Ingest none = publish(bus, team);
                String noneConditions = quiet.since();
                try (ViewerCrowd viewers = new ViewerCrowd(server, viewerCount, stalled, clock)) {
                    RoundConditions watchedConditions = new RoundConditions();
                    Ingest watched = publish(bus, team);
                    ServeStats s = server.stats();
                    System.out.printf(Locale.ROOT, "round %d: no viewers %.0f/s %.2f µs CPU each; %d viewers %.0f/s %.2f µs "
                                    + "CPU each (rate %.1f %%); sent %d, dropped %d%n", r + 1, none.rate, none.cpuNanos / 1e3,
                            viewerCount, watched.rate, watched.cpuNanos / 1e3, 100 * watched.rate / none.rate, s.sent(), s.dropped());
                    System.out.println("  no viewers: " + noneConditions);
                    System.out.println("  viewers:    " + watchedConditions.since());
                    viewers.print("latency");
                }
            }
        }
        return 0;
    }

    /** Publishes the team's envelopes (time-stamped now) at {@code rate} for {@code seconds}, in 10 ms steps. */
    private Ingest publish(EnvelopeBus bus, List<Envelope> team) {
        long start = System.nanoTime();
        long cpuStart = threads.getCurrentThreadCpuTime();
        long cpuInAccept = 0;
        long n = 0;
        int i = 0;
        long total = (long) rate * seconds;
        while (n < total) {
            long due = Math.min(total, (System.nanoTime() - start) * rate / 1_000_000_000L);
            long before = threads.getCurrentThreadCpuTime();
            for (; n < due; n++) {
                Envelope e = team.get(i);
                i = i + 1 == team.size() ? 0 : i + 1;
                bus.accept(new Envelope(clock.nowMicros(), e.direction(), e.channel(), e.peer(), e.robotId(), e.kind(),
                        e.message(), e.raw(), e.error()));
            }
            cpuInAccept += threads.getCurrentThreadCpuTime() - before;
            LockSupport.parkNanos(10_000_000L);
        }
        double secs = (System.nanoTime() - start) / 1e9;
        return new Ingest(n / secs, n == 0 ? 0 : (double) cpuInAccept / n);
    }
}
