package touchline.transport.gamecontroller;

import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.protocol.gamecontroller.HlGameState12;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * {@code touchline bench gc}: runs the GameController sender on loopback for a while (default
 * 10 min, {@code --seconds N}) and measures the receive intervals against the 500 ms budget
 * (±2 ms at p99). Beside it, in the same run, a baseline sender in the style of the official
 * Java GameController (send, then sleep 500 ms) is measured the same way. Optional
 * {@code --load-threads N} busy threads stand in for a loaded console; the first
 * {@code --warmup N} seconds (default 10) are not measured. {@code --realtime} gives our sender
 * (and both receivers, not the baseline sender) SCHED_RR like {@code touchline gc --realtime}.
 */
public final class GcIntervalBenchmark {

    private static final long INTERVAL_MS = 500;
    /** With --realtime the receiving probes get the same priority, so they do not add their own delay. */
    private static volatile boolean realtimeProbes;

    /** Receives datagrams on 127.0.0.1 and records receive times. */
    private static final class Probe implements AutoCloseable {
        final DatagramSocket socket;
        final List<Long> nanos = new ArrayList<>();
        final Thread thread;

        Probe(String name) throws IOException {
            socket = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0));
            thread = new Thread(this::loop, name);
            thread.setDaemon(true);
            thread.setPriority(Thread.MAX_PRIORITY);
            thread.start();
        }

        InetSocketAddress address() {
            return (InetSocketAddress) socket.getLocalSocketAddress();
        }

        private void loop() {
            if (realtimeProbes) {
                new RealtimePriority(10).applyToCurrentThread();
            }
            byte[] buf = new byte[2048];
            DatagramPacket p = new DatagramPacket(buf, buf.length);
            while (!socket.isClosed()) {
                try {
                    socket.receive(p);
                    long t = System.nanoTime();
                    synchronized (nanos) {
                        nanos.add(t);
                    }
                } catch (IOException e) {
                    return;
                }
            }
        }

        void reset() {
            synchronized (nanos) {
                nanos.clear();
            }
        }

        double[] deviationsMs() {
            synchronized (nanos) {
                double[] d = new double[Math.max(0, nanos.size() - 1)];
                for (int i = 1; i < nanos.size(); i++) {
                    d[i - 1] = (nanos.get(i) - nanos.get(i - 1)) / 1e6 - INTERVAL_MS;
                }
                return d;
            }
        }

        @Override
        public void close() {
            socket.close();
        }
    }

    public static void main(String[] args) throws Exception {
        int seconds = 600;
        int loadThreads = 0;
        int warmupSeconds = 10;
        boolean realtime = false;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--load-threads" -> loadThreads = Integer.parseInt(args[++i]);
                case "--warmup" -> warmupSeconds = Integer.parseInt(args[++i]);
                case "--realtime" -> realtime = true;
                default -> {
                    System.err.println("usage: GcIntervalBenchmark [--seconds N] [--load-threads N] [--warmup N] [--realtime]");
                    System.exit(2);
                }
            }
        }
        realtimeProbes = realtime;
        List<Thread> load = new ArrayList<>();
        for (int i = 0; i < loadThreads; i++) {
            Thread t = new Thread(GcIntervalBenchmark::busy, "load-" + i);
            t.setDaemon(true);
            t.start();
            load.add(t);
        }
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, GameClock.system());
        HlGameState12 format = new HlGameState12();
        try (Probe ours = new Probe("probe-touchline");
             Probe baseline = new Probe("probe-baseline");
             GcSender sender = new GcSender(p -> {
                 if (p) {
                     game.advance();
                 }
                 return game.controlData();
             }, List.of(format), List.of(ours.address()), null, e -> { }, INTERVAL_MS);
             DatagramSocket naive = new DatagramSocket()) {
            // Its own game: a shared lock would let the baseline thread delay ours (priority inversion).
            Game baselineGame = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, GameClock.system());
            Thread naiveSender = new Thread(() -> sleepAfterSend(naive, baselineGame, format, baseline.address()),
                    "baseline-sender");
            naiveSender.setDaemon(true);
            System.out.printf(Locale.ROOT, "measuring %d s on loopback after %d s warm-up, %d load thread(s), %d cores%n",
                    seconds, warmupSeconds, loadThreads, Runtime.getRuntime().availableProcessors());
            sender.useRealtimePriority(realtime);
            sender.start();
            naiveSender.start();
            // Intervals during start-up (JIT, thread set-up) are not part of the measurement.
            Thread.sleep(warmupSeconds * 1000L);
            ours.reset();
            baseline.reset();
            Thread.sleep(seconds * 1000L);
            naive.close();
            System.out.println("sender real-time priority: " + (sender.realtimeOutcome().isEmpty() ? "yes"
                    : sender.realtimeOutcome()));
            report("touchline GcSender (drift-free grid)", ours.deviationsMs());
            report("baseline: send, then sleep 500 ms (Java GC style)", baseline.deviationsMs());
        }
    }

    private static void sleepAfterSend(DatagramSocket socket, Game game, HlGameState12 format,
                                       InetSocketAddress to) {
        while (!socket.isClosed()) {
            try {
                byte[] b = format.encode(game.controlData());
                socket.send(new DatagramPacket(b, b.length, to));
                Thread.sleep(INTERVAL_MS);
            } catch (IOException | InterruptedException e) {
                return;
            }
        }
    }

    private static void report(String name, double[] dev) {
        if (dev.length == 0) {
            System.out.println(name + ": no intervals");
            return;
        }
        double[] abs = Arrays.stream(dev).map(Math::abs).sorted().toArray();
        double mean = Arrays.stream(dev).average().orElse(0);
        System.out.printf(Locale.ROOT,
                "%s: intervals %d, |deviation from 500 ms| p50 %.3f ms, p99 %.3f ms, max %.3f ms; "
                        + "mean interval %.3f ms%n",
                name, dev.length, pct(abs, 50), pct(abs, 99), abs[abs.length - 1], 500 + mean);
    }

    private static double pct(double[] sorted, double p) {
        int i = (int) Math.ceil(p / 100.0 * sorted.length) - 1;
        return sorted[Math.max(0, Math.min(sorted.length - 1, i))];
    }

    private static void busy() {
        long x = 0;
        while (true) {
            x += System.nanoTime() & 7;
            if (x == 42) {
                System.out.print("");
            }
        }
    }
}
