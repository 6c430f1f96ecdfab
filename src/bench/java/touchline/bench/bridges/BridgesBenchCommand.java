package touchline.bench.bridges;

import javafx.stage.Stage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.bridges.BridgeAddress;
import touchline.cli.FxThread;
import touchline.testing.RobotProcess;
import touchline.transport.UdpConfig;
import touchline.transport.remote.BridgeStatus;
import touchline.ui.window.ConsoleWindow;
import touchline.ui.window.LayoutNode;
import touchline.ui.window.LayoutNode.Branch;
import touchline.ui.window.LayoutNode.Entry;
import touchline.ui.window.LayoutNode.Leaf;
import touchline.ui.window.UiSettings;

import javax.imageio.ImageIO;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;

/**
 * Issue 39's performance budget: eight simulated ROS 2 robots ({@code sim_ros2_robot.py}, Foxglove
 * SDK servers on loopback) at about 100 messages a second each, one of them also sending a
 * 640×480 JPEG at 10 Hz, bridged into the console with the window open. First a baseline with no
 * view open (as {@code bench ui}), then every view open on the robots' topics; reports per phase
 * the message-to-screen latency (receive time to the pulse that shows it) and the window
 * process's CPU, and at the end what each robot sent to its subscribers against what the console
 * received. Run under {@code xvfb-run}.
 */
@Command(name = "bridges", mixinStandardHelpOptions = true,
        description = "Benchmark eight ROS 2 bridges into the window (nothing lost, message-to-screen p99, window CPU).")
public final class BridgesBenchCommand implements Callable<Integer> {

    @Option(names = "--robots", defaultValue = "8", description = "simulated ROS 2 robots (default ${DEFAULT-VALUE})")
    int robots;

    @Option(names = "--rate", defaultValue = "30", description = "the robots' --rate: pose, joints and heading each this"
            + " often a second, plus markers, camera, diagnostics, log and state: 30 is about 100 messages/s (default ${DEFAULT-VALUE})")
    int rate;

    @Option(names = "--camera-hz", defaultValue = "10", description = "the first robot's 640×480 JPEG per second (default ${DEFAULT-VALUE})")
    int cameraHz;

    @Option(names = "--baseline-seconds", defaultValue = "30", description = "seconds with no view open (default ${DEFAULT-VALUE})")
    int baselineSeconds;

    @Option(names = "--seconds", defaultValue = "60", description = "seconds with every view open (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--warmup-seconds", defaultValue = "10", description = "before each phase, this many not counted (default ${DEFAULT-VALUE})")
    int warmupSeconds;

    /** One phase's figures. */
    record Phase(String name, double p50, double p99, long shown, double cpuPercent, double fps) { }

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("touchline-bench-bridges");
        Path jpeg = dir.resolve("camera-640x480.jpg");
        writeCameraJpeg(jpeg);
        System.out.printf(Locale.ROOT, "camera JPEG 640×480, %d bytes%n", Files.size(jpeg));
        List<RobotProcess> sims = new ArrayList<>();
        try (Console console = new Console(ConsoleConfig.defaults().withUdp(
                UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start()) {
            for (int r = 1; r <= robots; r++) {
                List<String> cmd = new ArrayList<>(List.of("python3", "robot-side/ros2/sim_ros2_robot.py", "--port", "0",
                        "--name", "booster-" + r, "--rate", Integer.toString(rate), "--centre=" + (r - 4.5) + ",0",
                        "--seconds", Integer.toString(robotSeconds())));
                if (r == 1) {
                    cmd.addAll(List.of("--camera-jpeg", jpeg.toString(), "--camera-hz", Integer.toString(cameraHz)));
                }
                sims.add(RobotProcess.of(cmd).start());
            }
            FxThread.startToolkit();
            ConsoleWindow window = FxThread.call(() -> new ConsoleWindow(console,
                    new UiSettings(dir, true, false)).show(new Stage()));
            FxThread.run(() -> window.shell().restore(List.of()));
            List<Integer> ids = new ArrayList<>();
            for (int r = 1; r <= robots; r++) {
                ids.add(console.bridges().connect(BridgeAddress.parse("booster-" + r + "=ws://127.0.0.1:"
                        + sims.get(r - 1).port() + "/"), null));
            }
            if (!FxThread.await(() -> console.bridges().statuses().stream()
                    .filter(s -> s.connection().received() > 0).count() >= robots, 30_000)) {
                System.err.println("not every bridge connected and received: " + console.bridges().statuses());
                return 1;
            }
            Phase baseline = phase("views closed (baseline)", window, baselineSeconds);
            FxThread.run(() -> window.shell().restore(layout(ids)));
            Phase open = phase("views open", window, seconds);
            List<Delivery> deliveries = deliveries(console, sims, robotSeconds()); // the robots' whole run
            System.out.println();
            System.out.println("| phase | latency p50 | latency p99 | items shown | window process CPU, % of a core | fps |");
            System.out.println("|---|---|---|---|---|---|");
            System.out.println(row(baseline));
            System.out.println(row(open));
            System.out.printf(Locale.ROOT, "views open / closed CPU: %.2f%n", open.cpuPercent() / baseline.cpuPercent());
            System.out.println();
            System.out.println(Delivery.header());
            deliveries.forEach(d -> System.out.println(d.row()));
            console.bridges().statuses().stream().filter(s -> s.connection().unusable() > 0 || !s.undecodable().isEmpty())
                    .forEach(s -> System.out.println("  " + s.describe())); // why: the last unusable, undecodable by topic
            long lost = deliveries.stream().mapToLong(Delivery::lost).sum();
            System.out.printf(Locale.ROOT, "lost %d of %d; load average at the end %.1f%n", lost,
                    deliveries.stream().mapToLong(Delivery::sent).sum(),
                    ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
            FxThread.run(javafx.application.Platform::exit);
            return 0;
        } finally {
            for (RobotProcess sim : sims) {
                sim.close();
            }
        }
    }

    /**
     * How long the robots send: both phases with their warm-ups and {@link #START_MARGIN_SECONDS}
     * for the window and the bridges to come up. They stop by themselves and then print what they
     * sent (a SIGTERM under load did not always get that far).
     */
    private int robotSeconds() {
        return baselineSeconds + seconds + 2 * warmupSeconds + START_MARGIN_SECONDS;
    }

    private static final int START_MARGIN_SECONDS = 20;

    /** Waits for the robots to stop by themselves and say what they sent, then for the console's counts to settle. */
    private static List<Delivery> deliveries(Console console, List<RobotProcess> sims, double seconds) throws Exception {
        List<Long> sent = new ArrayList<>();
        for (RobotProcess sim : sims) {
            FxThread.await(() -> sim.stdout().contains("sent "), (START_MARGIN_SECONDS + 30) * 1000L);
            String out = sim.stdout();
            int i = out.lastIndexOf("sent ");
            sent.add(i < 0 ? -1 : Long.parseLong(out.substring(i + 5).trim().split("\\s+")[0]));
        }
        long total = -1;
        long now = received(console);
        while (now != total) { // the last messages on their way through the sockets
            total = now;
            Thread.sleep(500);
            now = received(console);
        }
        List<Delivery> out = new ArrayList<>();
        for (BridgeStatus s : console.bridges().statuses()) {
            int robot = Integer.parseInt(s.name().substring("booster-".length()));
            out.add(new Delivery(s.name(), sent.get(robot - 1), s.connection().received(), s.connection().unusable(),
                    s.undecodable().values().stream().mapToLong(Long::longValue).sum(), seconds));
        }
        return out;
    }

    private static long received(Console console) {
        return console.bridges().statuses().stream().mapToLong(s -> s.connection().received()).sum();
    }

    /** Every view kind on screen at once on the first robot's topics, the other robots' in tabs. */
    static List<LayoutNode> layout(List<Integer> ids) {
        List<Entry> fields = new ArrayList<>();
        List<Entry> tables = new ArrayList<>();
        List<Entry> plots = new ArrayList<>();
        for (int id : ids) {
            fields.add(new Entry("field", id + "//markers"));
            tables.add(new Entry("table", id + "//joint_states"));
            plots.add(new Entry("plot", id + "//heading"));
        }
        int first = ids.get(0);
        Leaf a = new Leaf(0, List.of(new Entry("robots", ""), new Entry("parameters", "")));
        Leaf b = new Leaf(0, List.of(new Entry("debug-console", "")));
        Leaf c = new Leaf(0, List.of(new Entry("network", ""), new Entry("ros-commands", "")));
        Leaf d = new Leaf(0, fields);
        Leaf e = new Leaf(0, List.of(new Entry("image", first + "//camera/image/compressed")));
        Leaf f = new Leaf(0, tables);
        Leaf g = new Leaf(0, plots);
        Leaf h = new Leaf(0, List.of(new Entry("text", first + "//robot_state"), new Entry("table", first + "//diagnostics")));
        Branch top = new Branch(false, List.of(0.25, 0.5, 0.75), List.of(a, b, c, d));
        Branch bottom = new Branch(false, List.of(0.25, 0.5, 0.75), List.of(e, f, g, h));
        return List.of(new Branch(true, List.of(0.5), List.of(top, bottom)));
    }

    private Phase phase(String name, ConsoleWindow window, int secs) throws Exception {
        System.out.printf(Locale.ROOT, "%s: %d s (warm-up %d s not counted)%n", name, secs, warmupSeconds);
        Thread.sleep(warmupSeconds * 1000L); // the phase runs; only its figures wait
        FxThread.run(() -> window.pulse().latency().reset());
        long frames = window.pulse().frames();
        long start = System.nanoTime();
        CpuMeter cpu = new CpuMeter(processCpuNanos(), start);
        Thread.sleep(secs * 1000L); // the phase's measured seconds
        long end = System.nanoTime();
        double percent = cpu.percentOfCore(processCpuNanos(), end);
        double fps = (window.pulse().frames() - frames) / ((end - start) / 1e9);
        Phase p = new Phase(name, window.pulse().latency().quantileMillis(0.5), window.pulse().latency().quantileMillis(0.99),
                window.pulse().latency().count(), percent, fps);
        System.out.println("  " + row(p));
        return p;
    }

    private static long processCpuNanos() {
        return ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : -1;
    }

    private static String row(Phase p) {
        return String.format(Locale.ROOT, "| %s | %s | %s | %d | %.1f %% | %.1f |", p.name(), ms(p.p50()), ms(p.p99()),
                p.shown(), p.cpuPercent(), p.fps());
    }

    private static String ms(double v) {
        return Double.isNaN(v) ? "–" : String.format(Locale.ROOT, "%.1f ms", v);
    }

    /** A camera's 640×480 picture (field, lines, ball, some sensor noise), JPEG at ImageIO's default quality. */
    private static void writeCameraJpeg(Path file) throws java.io.IOException {
        BufferedImage img = new BufferedImage(640, 480, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        g.setColor(new Color(120, 170, 230));
        g.fillRect(0, 0, 640, 160);
        g.setColor(new Color(40, 140, 50));
        g.fillRect(0, 160, 640, 320);
        g.setColor(Color.WHITE);
        g.fillRect(0, 300, 640, 6);
        g.fillOval(300, 360, 60, 60);
        g.dispose();
        Random noise = new Random(39);
        for (int y = 0; y < 480; y++) {
            for (int x = 0; x < 640; x++) {
                int rgb = img.getRGB(x, y);
                int n = noise.nextInt(25) - 12;
                int r = clamp(((rgb >> 16) & 255) + n);
                int gr = clamp(((rgb >> 8) & 255) + n);
                int b = clamp((rgb & 255) + n);
                img.setRGB(x, y, (r << 16) | (gr << 8) | b);
            }
        }
        ImageIO.write(img, "jpg", file.toFile());
    }

    private static int clamp(int v) {
        return Math.max(0, Math.min(255, v));
    }
}
