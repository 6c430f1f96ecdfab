package touchline;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.ProductVersion;
import touchline.testing.Requirement;
import touchline.testing.RobotProcess;

import java.io.IOException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * Issue 17's package, built and used as a user would: {@code packaging/package.sh} (what
 * {@code ./touchline package} runs) builds the .deb and the app image; the .deb is installed —
 * with {@code dpkg -i} into the real system when CI runs as root (removed again with
 * {@code dpkg -r}), else with {@code dpkg -x} into a scratch root — and the installed
 * {@code touchline} answers {@code --version}, a headless {@code listen} decodes the packaged
 * simulated robot on loopback, {@code record} records it and {@code replay --headless} plays
 * that recording and the packaged sample. The class-data archive for a fast start (made by the postinst, or
 * by its script where the package was only unpacked) serves the application's classes for the installed
 * class path, and under CI the installed launcher maps it. The installed size with the archive stays within
 * the 120 MB budget. About two minutes (one to build, the jlinked
 * runtime cached in target/package), so it is tagged slow; {@code ./touchline test} runs it.
 */
@Tag("integration")
@Tag("slow")
@Tag("package")
class PackageTest {

    private static final long BUDGET_KB = 120 * 1024;

    @TempDir
    Path scratch;

    @Test
    void theDebInstallsAndTheInstalledTouchlineRecordsDecodesAndReplays() throws Exception {
        for (String tool : List.of("jpackage", "jlink", "fakeroot", "dpkg-deb")) {
            Requirement.require(onPath(tool), tool + " is not installed (./touchline package installs what it needs)");
        }
        Requirement.robotSide("touchline-robot");
        Requirement.robotSide("touchline-nao-sim");
        String version = ProductVersion.ofThisBuild().version();

        Result built = run(List.of("bash", "packaging/package.sh"), 600, "TOUCHLINE_ROBOTSIDE_BIN",
                RobotProcess.binDir().toAbsolutePath().toString());
        assertEquals(0, built.exit(), "packaging/package.sh failed:\n" + built.output());
        Path deb = Path.of("target/package/touchline_" + version + "_amd64.deb");
        assertTrue(Files.isRegularFile(deb), deb + " was built (named by the version)");
        assertTrue(Files.isRegularFile(Path.of("target/package/touchline-" + version + "-linux-x64.tar.gz")),
                "the app image as .tar.gz");

        long installedKb = Long.parseLong(run(List.of("dpkg-deb", "-f", deb.toString(), "Installed-Size"), 30)
                .output().trim());
        assertTrue(installedKb <= BUDGET_KB, "installed size " + installedKb / 1024 + " MB over the 120 MB budget");
        String contents = run(List.of("dpkg-deb", "-c", deb.toString()), 60).output();
        for (String path : List.of("./usr/bin/touchline -> /opt/touchline/bin/touchline",
                "./usr/share/applications/touchline.desktop", "./usr/share/icons/hicolor/256x256/apps/touchline.png",
                "./opt/touchline/lib/runtime/bin/java", "./opt/touchline/lib/app/robot-side/touchline-robot",
                "./opt/touchline/lib/app/samples/demo-team.mcap", "./opt/touchline/lib/app/touchline.classlist",
                "./opt/touchline/lib/touchline-class-archive")) {
            assertTrue(contents.contains(path), "the package holds " + path);
        }
        String info = run(List.of("dpkg-deb", "-I", deb.toString()), 30).output();
        assertTrue(info.contains(" postinst") && info.contains(" postrm"), "the postinst makes the class archive:\n" + info);

        boolean system = Requirement.underCi() && "root".equals(System.getProperty("user.name"));
        Path root = system ? Path.of("/") : scratch.resolve("root");
        if (system) {
            Result installed = run(List.of("dpkg", "-i", deb.toString()), 300);
            assertEquals(0, installed.exit(), "dpkg -i:\n" + installed.output());
        } else {
            assertEquals(0, run(List.of("dpkg", "-x", deb.toString(), root.toString()), 120).exit());
        }
        try {
            Path touchline = system ? Path.of("/usr/bin/touchline") : root.resolve("opt/touchline/bin/touchline");
            Path app = root.resolve("opt/touchline/lib/app");
            String desktop = Files.readString(root.resolve("usr/share/applications/touchline.desktop"));
            assertTrue(desktop.contains("Exec=/opt/touchline/bin/touchline console"), desktop);

            Result v = run(List.of(touchline.toString(), "--version"), 120);
            assertEquals(0, v.exit(), v.output());
            assertEquals("Touchline " + version, v.output().lines().findFirst().orElse(""), v.output());

            long archiveKb = classArchiveServesTheInstalledClassPath(root, system);
            assertTrue(installedKb + archiveKb <= BUDGET_KB, "installed " + installedKb / 1024 + " MB and the class archive "
                    + archiveKb / 1024 + " MB: over the 120 MB budget");
            if (system) {
                launcherMapsTheArchive(touchline);
            }

            int port = freeUdpPort();
            try (RobotProcess robot = RobotProcess.of(List.of(app.resolve("robot-side/touchline-robot").toString(),
                    "--id", "4", "--team", "13", "--console", "127.0.0.1:" + port, "--port", "0")).start()) {
                Result listen = run(List.of(touchline.toString(), "listen", "--bind", "127.0.0.1", "--port",
                        Integer.toString(port), "--seconds", "6", "--quiet", "--table-every", "60"), 120);
                assertEquals(0, listen.exit(), listen.output());
                assertTrue(listen.output().contains("listening on UDP port " + port), listen.output());
                assertTrue(listen.output().lines().anyMatch(l -> l.startsWith("4 ") && l.contains("robot-4")
                        && l.contains("online")), "the installed listen decoded robot 4:\n" + listen.output());

                Path match = scratch.resolve("match.mcap");
                Result record = run(List.of(touchline.toString(), "record", "--bind", "127.0.0.1", "--port",
                        Integer.toString(port), "--seconds", "4", "--out", match.toString()), 120);
                assertEquals(0, record.exit(), record.output());
                Result played = run(List.of(touchline.toString(), "replay", "--headless", match.toString()), 120);
                assertEquals(0, played.exit(), tail(played.output()));
                assertTrue(played.output().contains(" robot 4 "), "the recording holds robot 4:\n" + tail(played.output()));
            }

            Result replay = run(List.of(touchline.toString(), "replay", "--headless",
                    app.resolve("samples/demo-team.mcap").toString()), 180);
            assertEquals(0, replay.exit(), tail(replay.output()));
            assertTrue(replay.output().contains("replayed 9295 envelopes"), tail(replay.output()));
        } finally {
            if (system) {
                Result removed = run(List.of("dpkg", "-r", "touchline"), 120);
                assertEquals(0, removed.exit(), "dpkg -r:\n" + removed.output());
                assertTrue(Files.notExists(SYSTEM_ARCHIVE_DIR), "the postrm removes " + SYSTEM_ARCHIVE_DIR);
            }
        }
    }

    private static final Path SYSTEM_ARCHIVE_DIR = Path.of("/var/cache/touchline");

    /**
     * The class-data archive of the installed console (the postinst's, or made here by the same script into a
     * scratch directory where the package was only unpacked) serves the application's classes for the class
     * path the launcher builds from the installed touchline.cfg: -Xshare:on fails when it does not map, and
     * the class-load log names where touchline.cli.Main came from. Returns the archive's size in KB.
     */
    private long classArchiveServesTheInstalledClassPath(Path root, boolean system) throws Exception {
        Path lib = root.resolve("opt/touchline/lib");
        Path dir = system ? SYSTEM_ARCHIVE_DIR : scratch.resolve("cache");
        if (!system) {
            Result made = run(List.of(lib.resolve("touchline-class-archive").toString(), dir.toString()), 600);
            assertEquals(0, made.exit(), made.output());
        }
        Path archive = dir.resolve("touchline.jsa");
        assertTrue(Files.isRegularFile(archive), archive + " was made (postinst: " + system + ")");
        String cfg = Files.readString(lib.resolve("app/touchline.cfg"));
        assertTrue(cfg.contains("java-options=-XX:SharedArchiveFile=" + SYSTEM_ARCHIVE_DIR.resolve("touchline.jsa")),
                "the launcher maps the archive:\n" + cfg);
        String appDir = lib.resolve("app").toString();
        String classPath = String.join(":", cfg.lines().filter(l -> l.startsWith("app.classpath=$APPDIR"))
                .map(l -> appDir + l.substring("app.classpath=$APPDIR".length())).toList());
        Result on = run(List.of(lib.resolve("runtime/bin/java").toString(), "-XX:+UseZGC", "-Xshare:on",
                "-XX:SharedArchiveFile=" + archive, "-Xlog:class+load=info", "-cp", classPath, "touchline.cli.Main",
                "--version"), 120);
        assertEquals(0, on.exit(), tail(on.output()));
        assertTrue(on.output().lines().anyMatch(l -> l.endsWith(" touchline.cli.Main source: shared objects file")),
                "touchline.cli.Main comes from the archive:\n" + tail(on.output()));
        return Files.size(archive) / 1024;
    }

    /** The installed launcher maps the postinst's archive: it shows in the process's memory map. */
    private void launcherMapsTheArchive(Path touchline) throws Exception {
        Process p = new ProcessBuilder(touchline.toString(), "listen", "--bind", "127.0.0.1", "--port",
                Integer.toString(freeUdpPort()), "--seconds", "20", "--quiet").redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        try {
            Path maps = Path.of("/proc", Long.toString(p.pid()), "maps");
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            boolean mapped = false;
            while (!mapped && p.isAlive() && System.nanoTime() < deadline) {
                mapped = Files.readString(maps).contains(SYSTEM_ARCHIVE_DIR.resolve("touchline.jsa").toString());
                if (!mapped) {
                    TimeUnit.MILLISECONDS.sleep(50); // polling the JVM's memory map, not synchronisation
                }
            }
            assertTrue(mapped, "the installed launcher's JVM maps " + SYSTEM_ARCHIVE_DIR.resolve("touchline.jsa"));
        } finally {
            p.destroy();
            p.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static String tail(String s) {
        return s.length() > 3000 ? "…" + s.substring(s.length() - 3000) : s;
    }

    private static boolean onPath(String tool) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(":")) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, tool))) {
                return true;
            }
        }
        return false;
    }

    private static int freeUdpPort() throws IOException {
        try (DatagramSocket s = new DatagramSocket(0, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    private record Result(int exit, String output) {
    }

    /** Runs a command to its end (stdout and stderr together), failing the test after {@code seconds}. */
    private Result run(List<String> command, long seconds, String... env) throws Exception {
        Path out = Files.createTempFile(scratch, "out", ".txt");
        ProcessBuilder pb = new ProcessBuilder(new ArrayList<>(command)).redirectErrorStream(true)
                .redirectOutput(out.toFile());
        for (int i = 0; i + 1 < env.length; i += 2) {
            pb.environment().put(env[i], env[i + 1]);
        }
        Process p = pb.start();
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            fail(String.join(" ", command) + " did not finish in " + seconds + " s:\n"
                    + tail(Files.readString(out, StandardCharsets.UTF_8)));
        }
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8));
    }
}
