package touchline.bench.gc;

import touchline.app.game.EmbeddedGameController;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;
import touchline.transport.gamecontroller.GcSender;
import touchline.transport.gamecontroller.MonitorService;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.game.hsl.Competition;
import touchline.game.hsl.FreeSetPlay;
import touchline.game.hsl.HslAction;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.game.hsl.SetPlay;
import touchline.game.hsl.HslStartSetPlay;
import touchline.game.hsl.StopPlay;
import touchline.game.hsl.WaitForSetPlay;
import touchline.protocol.gamecontroller.HlGameState12;
import touchline.protocol.gamecontroller.HslGameState20;
import touchline.protocol.gamecontroller.TeamColour;

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
 * {@code --hsl} measures the HSL schedule instead: an hsl20 game is stopped every 5 s, and the
 * stop-to-datagram latency, the burst's 200 ms and the grid's 500 ms are reported apart.
 * {@code --monitor-flood N} measures the embedded HSL GameController's 500 ms grid while N
 * monitor requests a second arrive, each from a new loopback host (127.1.0.1 upwards).
 */
public final class GcIntervalBenchmark {

    private static final long INTERVAL_MS = 500;
    /** HSL mode: how often play is stopped (and resumed halfway between). */
    private static final long STOP_EVERY_MS = 5_000;

    /** Runs from the command line's arguments; returns the exit status (2: a wrong argument). */
    public static int run(String[] args) throws Exception {
        int seconds = 600;
        int loadThreads = 0;
        int warmupSeconds = 10;
        boolean realtime = false;
        boolean hsl = false;
        int monitorFlood = 0;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--seconds" -> seconds = Integer.parseInt(args[++i]);
                case "--load-threads" -> loadThreads = Integer.parseInt(args[++i]);
                case "--warmup" -> warmupSeconds = Integer.parseInt(args[++i]);
                case "--realtime" -> realtime = true;
                case "--hsl" -> hsl = true;
                case "--monitor-flood" -> monitorFlood = Integer.parseInt(args[++i]);
                default -> {
                    System.err.println("usage: GcIntervalBenchmark [--seconds N] [--load-threads N] [--warmup N] [--realtime]"
                            + " [--hsl | --monitor-flood REQUESTS_PER_SECOND]");
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
        if (hsl) {
            hslBursts(seconds, warmupSeconds, realtime);
            return 0;
        }
        if (monitorFlood > 0) {
            monitorFlood(monitorFlood, seconds, warmupSeconds, realtime);
            return 0;
        }
        Game game = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
        HlGameState12 format = new HlGameState12();
        // as the embedded GameController runs it: one owner changes the game, the sender reads its snapshots
        try (touchline.app.game.GameRuntime owner = new touchline.app.game.GameRuntime(game);
             GcIntervalProbe ours = new GcIntervalProbe("probe-touchline", INTERVAL_MS, realtime);
             GcIntervalProbe baseline = new GcIntervalProbe("probe-baseline", INTERVAL_MS, realtime);
             GcSender sender = new GcSender(p -> (p ? owner.timed() : owner.snapshot()).robots(),
                     List.of(format), List.of(ours.address()), null, e -> { }, INTERVAL_MS,
                     new touchline.app.SystemClock());
             DatagramSocket naive = new DatagramSocket()) {
            // Its own game: a shared lock would let the baseline thread delay ours (priority inversion).
            Game baselineGame = new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock());
            Thread naiveSender = new Thread(() -> sleepAfterSend(naive, baselineGame, format, baseline.address()),
                    "baseline-sender");
            naiveSender.setDaemon(true);
            System.out.printf(Locale.ROOT, "measuring %d s on loopback after %d s warm-up, %d load thread(s), %d cores%n",
                    seconds, warmupSeconds, loadThreads, Runtime.getRuntime().availableProcessors());
            sender.useRealtimePriority(realtime);
            owner.start();
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

    /**
     * The HSL schedule: an hsl20 game in play is stopped every {@link #STOP_EVERY_MS} and resumed
     * halfway between; the probe's receive times are judged by {@link BurstTiming}.
     */
    private static void hslBursts(int seconds, int warmupSeconds, boolean realtime) throws Exception {
        HslGame game = new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, new touchline.app.SystemClock());
        List<Long> stops = new ArrayList<>();
        // as the embedded GameController runs it: one owner changes the game, the sender reads its snapshots
        try (touchline.app.game.GameRuntime owner = new touchline.app.game.GameRuntime(game);
             GcIntervalProbe probe = new GcIntervalProbe("probe-touchline", INTERVAL_MS, realtime);
             GcSender sender = new GcSender(p -> (p ? owner.timed() : owner.snapshot()).robots(),
                     List.of(new HslGameState20()), List.of(probe.address()), null, e -> { }, INTERVAL_MS, true,
                     new touchline.app.SystemClock())) {
            owner.addListener(snapshot -> sender.changed(snapshot.robots().stopped()));
            owner.start();
            for (HslAction a : List.<HslAction>of(new HslStartSetPlay(5, SetPlay.KICK_OFF), new WaitForSetPlay(),
                    new FreeSetPlay())) {
                owner.perform(a).join();
            }
            System.out.printf(Locale.ROOT, "HSL schedule: stop every %d ms for %d s after %d s warm-up, %d cores%n",
                    STOP_EVERY_MS, seconds, warmupSeconds, Runtime.getRuntime().availableProcessors());
            sender.useRealtimePriority(realtime);
            sender.start();
            Thread.sleep(warmupSeconds * 1000L);
            probe.reset();
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                Thread.sleep(STOP_EVERY_MS / 2);
                stops.add(System.nanoTime());
                owner.perform(new StopPlay(false));
                Thread.sleep(STOP_EVERY_MS / 2);
                owner.perform(new StopPlay(true));
            }
            System.out.println("sender real-time priority: " + (sender.realtimeOutcome().isEmpty() ? "yes"
                    : sender.realtimeOutcome()));
            long[] stopNanos = stops.stream().mapToLong(Long::longValue).toArray();
            System.out.println("touchline GcSender, HSL schedule: "
                    + new BurstTiming(probe.receiveTimes(), stopNanos, INTERVAL_MS, GcSender.BURST_SPACING_MS)
                    .summary());
        }
    }

    /**
     * The embedded HSL GameController serving monitors while {@code perSecond} monitor requests
     * a second arrive, each from a new loopback host: the robots' intervals (500 ms grid,
     * nothing stopped) and what the monitor service made of the requests.
     */
    private static void monitorFlood(int perSecond, int seconds, int warmupSeconds, boolean realtime)
            throws Exception {
        HslGame game = new HslGame(HslRules.v7(Competition.MIDDLE_ADVANCED), 5,
                new TeamColour[]{TeamColour.RED, TeamColour.PURPLE}, 14,
                new TeamColour[]{TeamColour.BLUE, TeamColour.YELLOW}, new touchline.app.SystemClock());
        InetSocketAddress loopback = new InetSocketAddress(java.net.InetAddress.getLoopbackAddress(), 0);
        try (GcIntervalProbe probe = new GcIntervalProbe("probe-touchline", INTERVAL_MS, realtime);
             DatagramSocket monitorsPort = new DatagramSocket(new InetSocketAddress(0));
             EmbeddedGameController gc = new EmbeddedGameController(game, new GcConfig(GcProfile.HSL20, false,
                     List.of(probe.address()), null, loopback, null, INTERVAL_MS, realtime), e -> { }, null,
                     new touchline.app.SystemClock())) {
            MonitorService monitors = gc.serveMonitors(loopback, monitorsPort.getLocalPort(), monitorsPort.getLocalPort());
            System.out.printf(Locale.ROOT, "HSL GameController, %d monitor requests/s each from a new loopback host,"
                    + " %d s after %d s warm-up, %d cores%n", perSecond, seconds, warmupSeconds,
                    Runtime.getRuntime().availableProcessors());
            gc.start();
            try (MonitorFlood flood = new MonitorFlood(monitors.requestAddress(), perSecond)) {
                flood.start();
                Thread.sleep(warmupSeconds * 1000L);
                probe.reset();
                Thread.sleep(seconds * 1000L);
                flood.close();
                System.out.println("monitor flood: " + flood.summary());
            }
            System.out.println("sender real-time priority: " + (gc.realtimeOutcome().isEmpty() ? "yes"
                    : gc.realtimeOutcome()));
            System.out.println("monitors: " + monitors.stats().describe());
            System.out.println("touchline HSL GameController under the flood: " + probe.summary());
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
