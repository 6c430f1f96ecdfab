package touchline.bench.serve;

import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.serve.ServeConfig;
import touchline.serve.ServeStats;
import touchline.serve.Serving;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.MicrosClock;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.locks.LockSupport;

/**
 * {@code bench serve --udp}: the budget as the issue states it. A six-robot team's datagrams
 * (one loopback socket per robot) go to a started {@link Console} (transport, model, view
 * stores) served by the same {@link Serving} as {@code touchline serve}; alternating rounds
 * with no viewer and with the viewers subscribed to everything. Reported: datagrams the
 * console ingested per second (its transport's count) in each, their ratio, and each viewer's
 * latency from the datagram's receive time stamp (taken by the transport as it reads the
 * socket) to the frame arriving in the viewer.
 */
final class UdpServeRun implements Callable<Integer> {

    private final MicrosClock clock;
    private final List<Envelope> team;
    private final int rate;
    private final int seconds;
    private final int rounds;
    private final int viewerCount;
    private final boolean stalled;

    UdpServeRun(MicrosClock clock, List<Envelope> team, int rate, int seconds, int rounds, int viewerCount,
                boolean stalled) {
        this.clock = clock;
        this.team = team.stream().filter(e -> e.direction() == Direction.IN && e.channel() == Channel.FUMANOID
                && e.error() == null).toList();
        this.rate = rate;
        this.seconds = seconds;
        this.rounds = rounds;
        this.viewerCount = viewerCount;
        this.stalled = stalled;
    }

    @Override
    public Integer call() throws Exception {
        System.out.printf(Locale.ROOT, "serve benchmark (UDP into a whole console): %d rounds x %d s at %d datagrams/s "
                + "(%d datagrams of a six-robot team cycled), %d viewers%s%n", rounds, seconds, rate, team.size(),
                viewerCount, stalled ? " (one stalled)" : "");
        Map<Integer, DatagramSocket> robots = new HashMap<>();
        try (Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)), clock).start();
             Serving serving = new Serving(ServeConfig.defaults().withPort(0), console.field().kinds(), clock, console.field().bus(),
                     console.serving().stateChannels()).start()) {
            for (Envelope e : team) {
                if (!robots.containsKey(e.robotId())) {
                    robots.put(e.robotId(), new DatagramSocket(new InetSocketAddress("127.0.0.1", 0)));
                }
            }
            InetSocketAddress to = new InetSocketAddress(InetAddress.getLoopbackAddress(), console.field().port());
            send(console, robots, to, team.size()); // every channel exists before the viewers come
            drained(console);
            for (int r = 0; r < rounds; r++) {
                RoundConditions quiet = new RoundConditions();
                double none = send(console, robots, to, (long) rate * seconds);
                drained(console);
                String noneConditions = quiet.since();
                try (ViewerCrowd viewers = new ViewerCrowd(serving.server(), viewerCount, stalled, clock)) {
                    RoundConditions watchedConditions = new RoundConditions();
                    double watched = send(console, robots, to, (long) rate * seconds);
                    ServeStats s = serving.server().stats();
                    System.out.printf(Locale.ROOT, "round %d: ingest, no viewers %.0f/s; %d viewers %.0f/s (ratio %.1f %%); "
                            + "sent %d, dropped %d%n", r + 1, none, viewerCount, watched, 100 * watched / none, s.sent(),
                            s.dropped());
                    System.out.println("  no viewers: " + noneConditions);
                    System.out.println("  viewers:    " + watchedConditions.since());
                    viewers.print("datagram-to-frame");
                }
            }
        } finally {
            robots.values().forEach(DatagramSocket::close);
        }
        return 0;
    }

    /** Waits (at most 5 s) until the console has read what was sent, so no phase counts another's backlog. */
    private static void drained(Console console) throws InterruptedException {
        long deadline = System.nanoTime() + 5_000_000_000L;
        long last = -1;
        while (System.nanoTime() < deadline) {
            long now = console.field().transportCounts().datagramsIn();
            if (now == last) {
                return;
            }
            last = now;
            Thread.sleep(100); // polling the transport's count: nothing to wait on
        }
    }

    /** Sends {@code total} of the team's datagrams at the rate, in 10 ms steps; the console's ingest rate over that time. */
    private double send(Console console, Map<Integer, DatagramSocket> robots, InetSocketAddress to, long total)
            throws java.io.IOException {
        long inBefore = console.field().transportCounts().datagramsIn();
        long start = System.nanoTime();
        long n = 0;
        int i = 0;
        while (n < total) {
            long due = Math.min(total, (System.nanoTime() - start) * rate / 1_000_000_000L);
            for (; n < due; n++) {
                Envelope e = team.get(i);
                i = i + 1 == team.size() ? 0 : i + 1;
                robots.get(e.robotId()).send(new DatagramPacket(e.raw(), e.raw().length, to));
            }
            LockSupport.parkNanos(10_000_000L);
        }
        double secs = (System.nanoTime() - start) / 1e9;
        return (console.field().transportCounts().datagramsIn() - inBefore) / secs;
    }
}
