package touchline.bench;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

/**
 * Issue 17's start budget: from a click on the desktop entry to the window, ≤ 3 s, the same as
 * the console's own start. The .deb is unpacked ({@code dpkg -x}) into a scratch root, its
 * desktop entry's Exec line is started (with the scratch root's path), and the time until a
 * window titled "Touchline …" is mapped and visible is taken by polling {@code xdotool search
 * --onlyvisible} every 20 ms. With {@code --root DIR} the package is the one installed in DIR (by
 * {@code apt-get install} in {@code packaging/check-fresh.sh --keep}'s Debian root, postinst and class-data
 * archive included) and the Exec line runs there through {@code chroot}. Baseline, alternating in the
 * same run: the developer launcher, {@code ./touchline console} (the built jar with its class-data archive).
 * Both get {@code --port 0} so a running demo's port 11011 does not stop them. Needs a display:
 * {@code xvfb-run -a ./touchline bench start}.
 */
@Command(name = "start", mixinStandardHelpOptions = true,
        description = "Desktop entry to window: the packaged console's start against the developer launcher's.")
final class StartBenchCommand implements Callable<Integer> {

    @Option(names = "--deb", description = "the package (default: target/package/touchline_<version>_amd64.deb)")
    Path deb;

    @Option(names = "--root", description = "a root the package is installed in (e.g. kept by packaging/check-fresh.sh "
            + "--keep, with its /proc and /dev mounted): the desktop entry's command runs there through chroot, with "
            + "the class-data archive its postinst made (needs root)")
    Path installedRoot;

    @Option(names = "--rounds", defaultValue = "5", description = "starts of each (default ${DEFAULT-VALUE})")
    int rounds;

    @Option(names = "--console", description = "only ./touchline console, with and without class-data sharing, "
            + "to its window and to the first robot's data (no package needed)")
    boolean consoleOnly;

    @Option(names = "--demo", description = "with --console: ./touchline demo --insecure too (needs port 11011 free)")
    boolean demo;

    @Override
    public Integer call() throws Exception {
        if (System.getenv("DISPLAY") == null) {
            System.err.println("bench start needs a display: xvfb-run -a ./touchline bench start");
            return 2;
        }
        if (consoleOnly) {
            return new ConsoleStartBench(rounds, demo).run();
        }
        List<String> packaged;
        Path root;
        if (installedRoot != null) {
            root = null;
            if (!Files.isRegularFile(installedRoot.resolve("proc/self/maps"))) {
                System.err.println(installedRoot + "/proc is not mounted: packaging/check-fresh.sh --keep leaves it mounted");
                return 2;
            }
            // the Exec line as it is, in the installed root; the display is this machine's (one network namespace),
            // its cookie (xvfb-run's) copied into the root
            packaged = new ArrayList<>(List.of("chroot", installedRoot.toString(), "/usr/bin/env", "-i",
                    "PATH=/usr/sbin:/usr/bin:/sbin:/bin", "HOME=/root", "LANG=C.UTF-8", "DISPLAY=" + System.getenv("DISPLAY")));
            String xauthority = System.getenv("XAUTHORITY");
            if (xauthority != null && Files.isRegularFile(Path.of(xauthority))) {
                Files.copy(Path.of(xauthority), installedRoot.resolve("tmp/touchline-bench.xauth"),
                        java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                packaged.add("XAUTHORITY=/tmp/touchline-bench.xauth");
            }
            packaged.addAll(Arrays.asList(desktopExec(installedRoot).split(" ")));
        } else {
            String version = touchline.app.ProductVersion.ofThisBuild().version();
            Path pkg = deb != null ? deb : Path.of("target/package/touchline_" + version + "_amd64.deb");
            if (!Files.isRegularFile(pkg)) {
                System.err.println(pkg + " missing: ./touchline package builds it");
                return 2;
            }
            root = Files.createTempDirectory("touchline-start-bench");
            run(List.of("dpkg", "-x", pkg.toString(), root.toString()));
            packaged = new ArrayList<>(Arrays.asList(desktopExec(root).replace("/opt/touchline", root + "/opt/touchline")
                    .split(" ")));
        }
        packaged.addAll(List.of("--port", "0"));
        // the developer launcher as a developer starts the console: the built jar with its class-data archive
        List<String> developer = List.of("./touchline", "console", "--port", "0");
        // one start of each first, unmeasured: the developer launcher's JavaFX unpacks its natives into
        // ~/.openjfx/cache once (the package's lie beside its jar), and the launcher trains its archive for a new build
        windowAfter(packaged);
        windowAfter(developer);
        double[] pkgSeconds = new double[rounds];
        double[] devSeconds = new double[rounds];
        for (int i = 0; i < rounds; i++) {
            pkgSeconds[i] = windowAfter(packaged);
            devSeconds[i] = windowAfter(developer);
            System.out.printf("round %d: desktop entry %.2f s, developer launcher %.2f s%n", i + 1, pkgSeconds[i],
                    devSeconds[i]);
        }
        double pkgMedian = median(pkgSeconds);
        double devMedian = median(devSeconds);
        System.out.printf("desktop entry to window: median %.2f s (max %.2f s), budget 3 s: %s%n", pkgMedian,
                Arrays.stream(pkgSeconds).max().orElse(0), pkgMedian <= 3 ? "met" : "MISSED");
        System.out.printf("developer launcher (baseline): median %.2f s; ratio %.2f%n", devMedian, pkgMedian / devMedian);
        if (root != null) {
            run(List.of("rm", "-rf", root.toString()));
        }
        return 0;
    }

    private static String desktopExec(Path root) throws IOException {
        return Files.readAllLines(root.resolve("usr/share/applications/touchline.desktop")).stream()
                .filter(l -> l.startsWith("Exec=")).findFirst().orElseThrow().substring(5);
    }

    /** Seconds from starting {@code command} until its window is visible; the process is stopped after. */
    private static double windowAfter(List<String> command) throws Exception {
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            return windowAfter(p, t0, String.join(" ", command));
        } finally {
            stop(p);
        }
    }

    /** Seconds from {@code t0} until a Touchline window is visible, or an exception when {@code p} ends first. */
    static double windowAfter(Process p, long t0, String command) throws Exception {
        long deadline = t0 + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            if (visible()) {
                return (System.nanoTime() - t0) / 1e9;
            }
            if (!p.isAlive()) {
                throw new IOException(command + " ended with " + p.exitValue() + " before its window showed");
            }
            TimeUnit.MILLISECONDS.sleep(20); // polling interval of the measurement, not synchronisation
        }
        throw new IOException("no window within 60 s: " + command);
    }

    /** Stops {@code p} and what it started, and waits until the window is gone. */
    static void stop(Process p) throws Exception {
        p.descendants().forEach(ProcessHandle::destroy);
        p.destroy();
        if (!p.waitFor(10, TimeUnit.SECONDS)) {
            p.destroyForcibly().waitFor();
        }
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (visible() && System.nanoTime() < deadline) {
            TimeUnit.MILLISECONDS.sleep(20); // polling for the old window to go, not synchronisation
        }
    }

    private static boolean visible() throws IOException, InterruptedException {
        Process x = new ProcessBuilder("xdotool", "search", "--onlyvisible", "--name", "^Touchline ")
                .redirectErrorStream(true).start();
        String out = new String(x.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        x.waitFor();
        return x.exitValue() == 0 && !out.isEmpty();
    }

    private static void run(List<String> command) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(command).inheritIO().start();
        if (p.waitFor() != 0) {
            throw new IOException(String.join(" ", command) + " failed");
        }
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
