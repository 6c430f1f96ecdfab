package touchline.bench;

import java.io.IOException;
import java.net.DatagramSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Issue 14's "light on the laptop" budgets: the console window on the demo team (three simulated
 * robots behind the simulated serial Wi-Fi module, the demo layout, the demo options switched on)
 * for some minutes; the console's CPU from {@code /proc/PID/stat} (user + system time, after a
 * warm-up) and its PSS from {@code /proc/PID/smaps_rollup}. The baseline, in the same run and
 * with the same robots: the headless {@code listen} (output discarded). The console runs as its
 * own JVM with the launcher's window options (ZGC, 512 MB heap), so the figures are the
 * console's and not this benchmark's. Run under {@code xvfb-run}.
 */
final class LaptopLoadBench {

    /** One phase's figures: CPU as a fraction of one core, PSS at the end and the highest seen. */
    record Load(String name, double coreFraction, double pssEndMb, double pssMaxMb, double seconds) { }

    private final int minutes;
    private final int baselineMinutes;
    private final int warmupSeconds;
    private final List<String> windowJvm;
    private final int idleMinutes;
    /** The window's {@code --max-fps} caps, one phase each, in this order (the standard: 30). */
    private final List<Integer> maxFps;

    /** From JDK 24: native libraries and sun.misc.Unsafe allowed, without the JVM's warnings (the launcher's JVM_OPTS). */
    static final List<String> QUIET_JDK24 = List.of("--enable-native-access=ALL-UNNAMED", "--sun-misc-unsafe-memory-access=allow");
    /** From JDK 25: compact object headers (the launcher's JVM_OPTS). */
    static final List<String> LEANER_JDK25 = List.of("-XX:+UseCompactObjectHeaders");
    /** The launcher's JVM options for the window ({@code ./touchline}: JVM_OPTS and UI_HEAP). */
    static final String WINDOW_JVM = "-XX:+UseZGC -Xmx512m -XX:SoftMaxHeapSize=256m -XX:ZUncommitDelay=10";

    LaptopLoadBench(int minutes, int baselineMinutes, int warmupSeconds, List<String> windowJvm, int idleMinutes,
                    List<Integer> maxFps) {
        this.maxFps = maxFps;
        this.idleMinutes = idleMinutes;
        this.minutes = minutes;
        this.baselineMinutes = baselineMinutes;
        this.warmupSeconds = warmupSeconds;
        this.windowJvm = windowJvm;
    }

    int run() throws Exception {
        int port;
        try (DatagramSocket probe = new DatagramSocket(0)) {
            port = probe.getLocalPort();
        }
        String bin = System.getProperty("touchline.robotside.bin", "robot-side/build/bin");
        Path scratch = Files.createTempDirectory("touchline-laptop-bench");
        List<Process> team = new ArrayList<>();
        try {
            for (int id = 1; id <= 3; id++) { // as ./touchline demo starts them
                team.add(new ProcessBuilder(Path.of(bin, "touchline-robot").toString(), "--id", String.valueOf(id),
                        "--team", "13", "--console", "127.0.0.1:" + port, "--port", String.valueOf(25000 + id * 10),
                        "--wifi-sim").redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start());
            }
            List<Load> loads = new ArrayList<>();
            if (baselineMinutes > 0) {
                loads.add(measure("headless listen (baseline)", List.of("listen", "--port", String.valueOf(port),
                        "--team", "13", "--insecure"), false, baselineMinutes));
            }
            if (idleMinutes > 0) {
                int quiet;
                try (DatagramSocket probe = new DatagramSocket(0)) {
                    quiet = probe.getLocalPort(); // no robot sends here: the window has nothing to show
                }
                loads.add(measure("window, demo layout, no robot sending", List.of("console", "--demo", "--team", "13",
                        "--insecure", "--port", String.valueOf(quiet), "--layouts", scratch.toString()), true, idleMinutes));
            }
            Load standard = null;
            for (int cap : maxFps) {
                Load l = measure(cap == touchline.ui.frame.FrameCap.DEFAULT ? "window, demo layout"
                        : "window, demo layout, --max-fps " + cap, List.of("console", "--demo", "--team", "13", "--insecure",
                        "--port", String.valueOf(port), "--layouts", scratch.toString(), "--max-fps", String.valueOf(cap)),
                        true, minutes);
                loads.add(l);
                if (cap == touchline.ui.frame.FrameCap.DEFAULT || standard == null) {
                    standard = l;
                }
            }
            System.out.println();
            System.out.println("| phase | minutes | console CPU (of one core) | PSS at the end | PSS max |");
            System.out.println("|---|---|---|---|---|");
            for (Load l : loads) {
                System.out.printf(Locale.ROOT, "| %s | %.1f | %.1f %% | %.0f MB | %.0f MB |%n", l.name(), l.seconds() / 60,
                        l.coreFraction() * 100, l.pssEndMb(), l.pssMaxMb());
            }
            Load window = standard; // the budget is the console as it starts: the standard cap
            System.out.printf(Locale.ROOT, "budgets: CPU <= 15 %% of one core: %s; PSS <= 500 MB: %s%n",
                    window.coreFraction() <= 0.15 ? "met" : "MISSED", window.pssEndMb() <= 500 ? "met" : "MISSED");
            if (baselineMinutes > 0) { // the headless listen is the first phase
                System.out.printf(Locale.ROOT, "window / baseline: CPU %.2f, PSS %.2f%n",
                        window.coreFraction() / loads.get(0).coreFraction(), window.pssEndMb() / loads.get(0).pssEndMb());
            }
        } finally {
            team.forEach(Process::destroy);
        }
        return 0;
    }

    private Load measure(String name, List<String> args, boolean window, int phaseMinutes) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(ProcessHandle.current().info().command().orElse("java")));
        cmd.addAll(window ? windowJvm : List.of("-XX:+UseZGC"));
        if (Runtime.version().feature() >= 24) {
            cmd.addAll(QUIET_JDK24); // as the launcher runs it (./touchline, JVM_OPTS)
        }
        if (Runtime.version().feature() >= 25) {
            cmd.addAll(LEANER_JDK25);
        }
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"),
                "-Dtouchline.robotside.bin=" + System.getProperty("touchline.robotside.bin", "robot-side/build/bin"),
                "touchline.cli.Main"));
        cmd.addAll(args);
        System.out.printf(Locale.ROOT, "%s: %d s warm-up, then %d min; %s%n", name, warmupSeconds, phaseMinutes,
                String.join(" ", cmd.subList(1, cmd.indexOf("-cp"))));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            Thread.sleep(warmupSeconds * 1000L);
            long ticks0 = cpuTicks(p.pid());
            long t0 = System.nanoTime();
            double pssMax = 0;
            double pss = 0;
            for (int s = 1; s <= phaseMinutes * 60; s++) {
                Thread.sleep(Math.max(0, t0 + s * 1_000_000_000L - System.nanoTime()) / 1_000_000);
                if (!p.isAlive()) {
                    throw new IOException(name + ": the console ended (exit " + p.exitValue() + ")");
                }
                if (s % 10 == 0) {
                    pss = pssMb(p.pid());
                    pssMax = Math.max(pssMax, pss);
                    double secs = (System.nanoTime() - t0) / 1e9;
                    System.out.printf(Locale.ROOT, "  %4d s  CPU %5.1f %% of a core  PSS %5.0f MB%n", s,
                            (cpuTicks(p.pid()) - ticks0) / TICKS_PER_SECOND / secs * 100, pss);
                }
            }
            double secs = (System.nanoTime() - t0) / 1e9;
            double core = (cpuTicks(p.pid()) - ticks0) / TICKS_PER_SECOND / secs;
            return new Load(name, core, pss, pssMax, secs);
        } finally {
            p.destroy();
            if (!p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }

    /** USER_HZ: clock ticks per second of /proc's times; 100 on Linux x86-64. */
    private static final double TICKS_PER_SECOND = 100;

    /** User + system time of a process in clock ticks (fields 14 and 15 of /proc/PID/stat). */
    static long cpuTicks(long pid) throws IOException {
        String stat = Files.readString(Path.of("/proc", String.valueOf(pid), "stat"));
        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        return Long.parseLong(f[11]) + Long.parseLong(f[12]); // fields 14, 15 counted from field 3
    }

    /** Proportional set size in MB (the Pss line of /proc/PID/smaps_rollup, in kB). */
    static double pssMb(long pid) throws IOException {
        for (String line : Files.readAllLines(Path.of("/proc", String.valueOf(pid), "smaps_rollup"))) {
            if (line.startsWith("Pss:")) {
                return Long.parseLong(line.replaceAll("[^0-9]", "")) / 1024.0;
            }
        }
        throw new IOException("no Pss line in /proc/" + pid + "/smaps_rollup");
    }
}
