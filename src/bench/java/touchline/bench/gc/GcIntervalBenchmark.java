package touchline.bench.gc;

import touchline.transport.gamecontroller.GcSender;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.protocol.gamecontroller.HlGameState12;

import java.io.IOException;
import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.ArrayList;
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
    /** Runs from the command line's arguments; returns the exit status (2: a wrong argument). */
    public static int run(String[] args) throws Exception {
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
                    return 2;
                }
            }
        }
        List<Thread> load = new ArrayList<>();
        for (int i = 0; i < loadThreads; i++) {
            Thread t = new Thread(GcIntervalBenchmark::busy, "load-" + i);
            t.setDaemon(true);
            t.start();
            load.add(t);
        }
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, GameClock.system());
        HlGameState12 format = new HlGameState12();
        try (GcIntervalProbe ours = new GcIntervalProbe("probe-touchline", INTERVAL_MS, realtime);
             GcIntervalProbe baseline = new GcIntervalProbe("probe-baseline", INTERVAL_MS, realtime);
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
            System.out.println("touchline GcSender (drift-free grid): " + ours.summary());
            System.out.println("baseline: send, then sleep 500 ms (Java GC style): " + baseline.summary());
        }
        return 0;
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
