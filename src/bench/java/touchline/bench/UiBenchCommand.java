package touchline.bench;

import touchline.cli.FxThread;
import touchline.cli.SimulatedTeam;
import javafx.stage.Stage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcConfig;
import touchline.bench.gc.GcIntervalProbe;
import touchline.transport.gamecontroller.GcProfile;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.UiSettings;
import touchline.ui.window.LayoutNode;
import touchline.ui.window.LayoutNode.Branch;
import touchline.ui.window.LayoutNode.Entry;
import touchline.ui.window.LayoutNode.Leaf;

import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * UI benchmark: the console window against simulated robots with every option on at a high
 * rate. First a baseline with no view open, then the same traffic with every kind of view
 * open; reports frames per second, packet-to-screen latency (datagram receive time to the
 * pulse that shows it), heap, and where the FX thread's time went. Run under {@code xvfb-run}.
 */
@Command(name = "ui", mixinStandardHelpOptions = true,
        description = "Benchmark the console UI (fps, packet-to-screen latency, heap) against simulated robots.")
public final class UiBenchCommand implements java.util.concurrent.Callable<Integer> {

    @Option(names = "--robots", defaultValue = "6", description = "simulated robots (default ${DEFAULT-VALUE})")
    int robots;

    @Option(names = "--rate", defaultValue = "50", description = "messages per second per option per robot (default ${DEFAULT-VALUE})")
    int rate;

    @Option(names = "--baseline-seconds", defaultValue = "60", description = "seconds with no view open (default ${DEFAULT-VALUE})")
    int baselineSeconds;

    @Option(names = "--seconds", defaultValue = "600", description = "seconds with the views open (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--warmup-seconds", defaultValue = "0", description = "before each phase's measured seconds, this many"
            + " not counted: the JIT compiling the views' and the viewers' code on two cores (default ${DEFAULT-VALUE};"
            + " the first 2 s of each phase are never counted)")
    int warmupSeconds;

    @Option(names = "--gc", description = "also referee inside the console (embedded GameController, HL v12 to a probe on"
            + " 127.0.0.1) and report its send intervals while the views are open")
    boolean gc;

    @Option(names = "--gc-no-realtime", description = "with --gc: the sender at default scheduling instead of real-time priority")
    boolean gcNoRealtime;

    @Option(names = "--viewers", defaultValue = "0", description = "then serve (as Serve to viewers does) to this many "
            + "viewers subscribed to every channel, with the views open, and measure the same again with serving off")
    int viewers;

    @Option(names = "--viewers-apart", description = "with --viewers: the viewers in a JVM of their own (as on other "
            + "machines: not in the window's heap), instead of in the window's JVM")
    boolean viewersApart;

    @Option(names = "--viewers-niced", description = "with --viewers-apart: the viewers' JVM at nice 19, so that it takes"
            + " only CPU the window leaves idle — standing in for viewers on other laptops, whose CPU is not the console's")
    boolean viewersNiced;

    @Option(names = "--laptop", description = "instead: issue 14's laptop budgets, the console's CPU and PSS on the demo"
            + " team and demo layout (its own JVM), against the headless listen in the same run")
    boolean laptop;

    @Option(names = "--laptop-minutes", defaultValue = "10", description = "with --laptop: minutes of the window (default ${DEFAULT-VALUE})")
    int laptopMinutes;

    @Option(names = "--laptop-baseline-minutes", defaultValue = "2",
            description = "with --laptop: minutes of the headless listen (0: none; default ${DEFAULT-VALUE})")
    int laptopBaselineMinutes;

    @Option(names = "--laptop-idle-minutes", defaultValue = "0",
            description = "with --laptop: first this many minutes of the window with no robot sending (default ${DEFAULT-VALUE})")
    int laptopIdleMinutes;

    @Option(names = "--laptop-jvm", defaultValue = LaptopLoadBench.WINDOW_JVM,
            description = "with --laptop: the window's JVM options, as the launcher gives them (default ${DEFAULT-VALUE})")
    String laptopJvm;

    @Option(names = "--laptop-max-fps", split = ",", defaultValue = "30",
            description = "with --laptop: the window's --max-fps, one phase each in this order, e.g. 30,10 (default ${DEFAULT-VALUE})")
    List<Integer> laptopMaxFps;

    @Option(names = "--only", description = "open only this view (by registry ID) instead of every view, e.g. to find a slow one")
    String only;


    /** One phase's figures. */
    record Phase(String name, double fpsMean, double fpsMin, double p50, double p99, long shown, double packetsPerSecond,
                 double heapMaxMb, double heapAfterGcFirstMinuteMb, double heapAfterGcEndMb, Map<String, Long> viewNanos,
                 long frames, double pullsPerSecond) { }

    @Override
    public Integer call() throws Exception {
        if (laptop) {
            return new LaptopLoadBench(laptopMinutes, laptopBaselineMinutes, 30, List.of(laptopJvm.trim().split("\\s+")), laptopIdleMinutes,
                    laptopMaxFps).run();
        }
        try (Console console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
             SimulatedTeam team = SimulatedTeam.start(robots, console.field().port(), List.of("--rate", Integer.toString(rate)))) {
            FxThread.startToolkit();
            ConsoleWindow window = FxThread.call(() -> new ConsoleWindow(console,
                    new UiSettings(tempDir(), true, false)).show(new Stage()));
            FxThread.run(() -> window.shell().restore(List.of()));
            if (!FxThread.await(() -> allListsIn(console), 30_000)) {
                System.err.println("not every simulated robot sent its option list");
                return 1;
            }
            int switched = 0;
            for (RobotSnapshot r : console.field().robots().robots()) {
                for (OptionState o : console.field().options().options(r.id()).options()) {
                    console.optionSwitches().set(r.id(), o.name(), true);
                    switched++;
                }
            }
            System.out.printf(Locale.ROOT, "%d robots, %d options switched on at %d Hz%n", robots, switched, rate);
            FxThread.await(() -> false, 5_000); // let every stream start
            GcIntervalProbe gcProbe = gc ? startGameController(console) : null;
            Phase baseline = phase("views closed (baseline)", console, window, baselineSeconds);
            List<LayoutNode> layout = only == null ? benchLayout(robots)
                    : List.of(new Leaf(0, List.of(new Entry(only, only.equals("field") ? "1/demo.field" : "1/" + sourceFor(only)))));
            FxThread.run(() -> window.shell().restore(layout));
            if (gcProbe != null) {
                gcProbe.reset();
            }
            Phase open = phase("views open", console, window, seconds);
            List<Phase> served = viewers > 0 ? servedPhases(console, window) : List.of();
            System.out.println();
            System.out.println(header());
            System.out.println(row(baseline));
            System.out.println(row(open));
            served.forEach(p -> System.out.println(row(p)));
            System.out.println();
            System.out.println("FX thread time per frame by view (views open):");
            open.viewNanos().forEach((id, ns) -> System.out.printf(Locale.ROOT, "  %-14s %.3f ms%n", id,
                    ns / 1e6 / Math.max(1, open.frames())));
            if (gcProbe != null) {
                String rt = console.referee().gameController().map(g -> g.sender().realtimeOutcome()).orElse("stopped");
                System.out.println();
                System.out.println("GameController inside the console, views open (sender real-time priority: "
                        + (rt.isEmpty() ? "yes" : rt) + "): " + gcProbe.summary());
                gcProbe.close();
            }
            FxThread.run(javafx.application.Platform::exit);
        }
        return 0;
    }

    /**
     * The views open and the console serving to {@link #viewers} viewers subscribed to every
     * channel (the server the window's Serve to viewers starts), then the views open with
     * serving off again, so the serving phase has a baseline on each side in the same run.
     */
    /** The server the window's Serve to viewers starts (ui.ServeToggle): the stream, match mode and the budget. */
    private static touchline.serve.Serving serving(Console console) throws InterruptedException {
        return new touchline.serve.Serving(touchline.serve.ServeConfig.defaults().withPort(0), console.field().kinds(),
                console.field().clock(), console.field().bus(), console.serving().stateChannels());
    }

    private List<Phase> servedPhases(Console console, ConsoleWindow window) throws Exception {
        touchline.transport.MicrosClock clock = console.field().clock();
        Phase on;
        if (viewersApart) {
            try (touchline.serve.Serving serving = serving(console)) {
                on = servedApart(serving, console, window);
            }
            return List.of(on, phase("views open, serving off again", console, window, seconds));
        }
        try (touchline.serve.Serving serving = serving(console);
             touchline.bench.serve.ViewerCrowd crowd = new touchline.bench.serve.ViewerCrowd(serving.server(), viewers,
                     false, clock)) {
            touchline.bench.serve.RoundConditions conditions = new touchline.bench.serve.RoundConditions();
            on = phase("views open, serving to " + viewers + " viewers", console, window, seconds);
            System.out.println("  " + crowd.summary() + "; sent " + serving.server().stats().sent() + ", dropped "
                    + serving.server().stats().dropped());
            System.out.println("  " + conditions.since());
        }
        Phase off = phase("views open, serving off again", console, window, seconds);
        return List.of(on, off);
    }

    /** The serving phase with the viewers in a JVM of their own ({@code ViewerCrowd}'s main). */
    private Phase servedApart(touchline.serve.Serving serving, Console console, ConsoleWindow window) throws Exception {
        List<String> command = new ArrayList<>();
        if (viewersNiced) {
            command.addAll(List.of("nice", "-n", "19"));
        }
        command.addAll(List.of(java.nio.file.Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:+UseZGC", "-cp", System.getProperty("java.class.path"), "touchline.bench.serve.ViewerCrowd",
                Integer.toString(serving.server().port()), Integer.toString(viewers)));
        Process crowd = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        try (java.io.BufferedReader out = new java.io.BufferedReader(new java.io.InputStreamReader(crowd.getInputStream(),
                java.nio.charset.StandardCharsets.UTF_8));
             java.io.Writer in = new java.io.OutputStreamWriter(crowd.getOutputStream(), java.nio.charset.StandardCharsets.UTF_8)) {
            out.readLine(); // "connected"
            long wanted = (long) serving.server().stats().channels() * viewers;
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (serving.server().stats().subscriptions() < wanted && System.nanoTime() < deadline) {
                Thread.sleep(10); // waiting for the viewers' subscriptions to arrive
            }
            in.write("go\n");
            in.flush();
            touchline.bench.serve.RoundConditions conditions = new touchline.bench.serve.RoundConditions();
            Phase on = phase("views open, serving to " + viewers + " viewers in another JVM" + (viewersNiced ? " at nice 19" : ""),
                    console, window, seconds);
            String windowSide = conditions.since();
            in.close();
            System.out.println("  " + out.readLine() + "; sent " + serving.server().stats().sent() + ", dropped "
                    + serving.server().stats().dropped());
            System.out.println("  the window's JVM: " + windowSide);
            return on;
        } finally {
            crowd.waitFor(10, java.util.concurrent.TimeUnit.SECONDS);
            crowd.destroy();
        }
    }

    /** The console referees a game (INITIAL: nothing held back) towards a probe on loopback. */
    private GcIntervalProbe startGameController(Console console) throws java.io.IOException {
        boolean realtime = !gcNoRealtime;
        GcIntervalProbe probe = new GcIntervalProbe("gc-probe", GcConfig.INTERVAL_MS, realtime);
        GcConfig config = new GcConfig(GcProfile.HL12, false, List.of(probe.address()), null,
                new InetSocketAddress("127.0.0.1", 0), null, GcConfig.INTERVAL_MS, realtime);
        console.referee().start(new Game(LeagueParams.hlSimulationKidSize(), 13, 1, 7, 0, new touchline.app.SystemClock()), config);
        return probe;
    }

    private static String sourceFor(String view) {
        return switch (view) {
            case "regions" -> "havimo.region";
            case "plot" -> "demo.plotter";
            case "image" -> "demo.image";
            case "text" -> "demo.text";
            case "relative" -> "demo.relative";
            case "table" -> "demo.table";
            default -> "";
        };
    }

    private static java.nio.file.Path tempDir() {
        try {
            return Files.createTempDirectory("touchline-bench-layouts");
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private boolean allListsIn(Console console) {
        List<RobotSnapshot> seen = console.field().robots().robots();
        return seen.size() >= robots && seen.stream().allMatch(r -> console.field().options().options(r.id()).listReceived());
    }

    /** Every view kind on screen at once (robot 1), the other robots' overlays and plots in tabs. */
    static List<LayoutNode> benchLayout(int robots) {
        List<Entry> overlays = new ArrayList<>();
        List<Entry> plots = new ArrayList<>();
        for (int r = 1; r <= robots; r++) {
            overlays.add(new Entry("regions", r + "/havimo.region"));
            plots.add(new Entry("plot", r + "/demo.plotter"));
        }
        Leaf a = new Leaf(0, List.of(new Entry("robots", ""), new Entry("options", "")));
        Leaf b = new Leaf(0, List.of(new Entry("debug-console", "")));
        Leaf c = new Leaf(0, List.of(new Entry("network", "")));
        Leaf d = new Leaf(0, List.of(new Entry("field", "1/demo.field")));
        Leaf e = new Leaf(0, overlays);
        Leaf f = new Leaf(0, plots);
        Leaf g = new Leaf(0, List.of(new Entry("image", "1/demo.image"), new Entry("text", "1/demo.text")));
        Leaf h = new Leaf(0, List.of(new Entry("relative", "1/demo.relative"), new Entry("table", "1/demo.table")));
        Branch top = new Branch(false, List.of(0.25, 0.5, 0.75), List.of(a, b, c, d));
        Branch bottom = new Branch(false, List.of(0.25, 0.5, 0.75), List.of(e, f, g, h));
        return List.of(new Branch(true, List.of(0.5), List.of(top, bottom)));
    }

    private Phase phase(String name, Console console, ConsoleWindow window, int secs) throws Exception {
        System.out.printf(Locale.ROOT, "%s: %d s%n", name, secs);
        if (warmupSeconds > 0) {
            System.out.printf(Locale.ROOT, "  warm-up %d s, not counted%n", warmupSeconds);
            Thread.sleep(warmupSeconds * 1000L); // the phase runs; only its figures wait
        }
        FxThread.run(() -> {
            window.pulse().latency().reset();
            window.pulse().takeRefreshNanos();
        });
        long startFrames = window.pulse().frames();
        long startPulls = window.pulse().workFrames();
        long startIn = console.field().transportCounts().datagramsIn();
        long start = System.nanoTime();
        double fpsSum = 0;
        double fpsMin = Double.MAX_VALUE;
        int samples = 0;
        double heapMax = 0;
        double heapFirstMinute = Double.NaN;
        Runtime rt = Runtime.getRuntime();
        for (int s = 1; s <= secs; s++) {
            Thread.sleep(Math.max(0, start + s * 1_000_000_000L - System.nanoTime()) / 1_000_000);
            double fps = window.pulse().fps();
            if (s > 2) { // the first seconds include building the views
                fpsSum += fps;
                fpsMin = Math.min(fpsMin, fps);
                samples++;
            }
            double used = (rt.totalMemory() - rt.freeMemory()) / 1e6;
            heapMax = Math.max(heapMax, used);
            if (s == Math.min(60, secs)) {
                heapFirstMinute = heapAfterGc(rt);
            }
            if (s % 10 == 0) {
                System.out.printf(Locale.ROOT, "  %4d s  %5.1f fps  p99 %6.1f ms  heap %6.1f MB  in %6.0f pkt/s%n", s, fps,
                        window.pulse().latency().quantileMillis(0.99), used,
                        (console.field().transportCounts().datagramsIn() - startIn) / ((System.nanoTime() - start) / 1e9));
            }
        }
        double elapsed = (System.nanoTime() - start) / 1e9;
        double pps = (console.field().transportCounts().datagramsIn() - startIn) / elapsed;
        Map<String, Long> nanos = FxThread.call(() -> window.pulse().takeRefreshNanos());
        long frames = window.pulse().frames() - startFrames;
        double pulls = (window.pulse().workFrames() - startPulls) / elapsed;
        double p50 = window.pulse().latency().quantileMillis(0.5);
        double p99 = window.pulse().latency().quantileMillis(0.99);
        long shown = window.pulse().latency().count();
        return new Phase(name, fpsSum / Math.max(1, samples), samples == 0 ? 0 : fpsMin, p50, p99, shown, pps, heapMax,
                heapFirstMinute, heapAfterGc(rt), nanos, frames, pulls);
    }

    private static double heapAfterGc(Runtime rt) {
        System.gc();
        return (rt.totalMemory() - rt.freeMemory()) / 1e6;
    }

    static String header() {
        return "| phase | fps mean | fps min | view pulls/s | latency p50 | latency p99 | items shown | packets/s in | heap max | heap after GC at 1 min | heap after GC at end |\n"
                + "|---|---|---|---|---|---|---|---|---|---|---|";
    }

    static String row(Phase p) {
        return String.format(Locale.ROOT, "| %s | %.1f | %.1f | %.1f | %s | %s | %d | %.0f | %.0f MB | %.0f MB | %.0f MB |",
                p.name(), p.fpsMean(), p.fpsMin(), p.pullsPerSecond(), ms(p.p50()), ms(p.p99()), p.shown(), p.packetsPerSecond(), p.heapMaxMb(),
                p.heapAfterGcFirstMinuteMb(), p.heapAfterGcEndMb());
    }

    private static String ms(double v) {
        return Double.isNaN(v) ? "–" : String.format(Locale.ROOT, "%.1f ms", v);
    }
}
