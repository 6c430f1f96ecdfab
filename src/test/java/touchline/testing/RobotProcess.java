package touchline.testing;

import touchline.cli.RobotSideBinaries;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A simulated robot-side binary (built by CMake into robot-side/build/bin) run as a real
 * process for integration tests. Reads the port it bound from its first stdout line
 * ({@code listening on port N}); stderr goes to the test's stderr.
 */
public final class RobotProcess implements AutoCloseable {

    private final List<String> command;
    private Process process;
    private int port;
    private final StringBuilder stdout = new StringBuilder();

    private RobotProcess(List<String> command) {
        this.command = command;
    }

    /** The directory the binaries are built into; tests skip (via Assumptions) when it is missing. */
    public static Path binDir() {
        return new RobotSideBinaries().dir();
    }

    public static boolean available(String binary) {
        return new RobotSideBinaries().isBuilt(binary);
    }

    /** A simulated small robot sending to the console at {@code consolePort} on loopback. */
    public static RobotProcess robot(int id, int consolePort, String... extra) {
        List<String> cmd = new ArrayList<>(List.of(binDir().resolve("touchline-robot").toString(),
                "--id", Integer.toString(id), "--team", "13", "--console", "127.0.0.1:" + consolePort, "--port", "0"));
        cmd.addAll(List.of(extra));
        return new RobotProcess(cmd);
    }

    public static RobotProcess of(List<String> command) {
        return new RobotProcess(command);
    }

    /** Starts the process and waits (up to 10 s) for its {@code listening on port N} line. */
    public RobotProcess start() throws IOException {
        process = new ProcessBuilder(command).redirectError(ProcessBuilder.Redirect.INHERIT).start();
        BufferedReader out = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        String line;
        while ((line = out.readLine()) != null) {
            int i = line.indexOf("listening on port ");
            if (i >= 0) {
                port = Integer.parseInt(line.substring(i + "listening on port ".length()).trim());
                break;
            }
            if (System.nanoTime() > deadline) {
                break;
            }
        }
        if (port == 0) {
            process.destroyForcibly();
            throw new IOException("robot process did not report its port: " + command);
        }
        Thread drain = new Thread(() -> {
            char[] buf = new char[4096];
            try {
                int n;
                while ((n = out.read(buf)) > 0) {
                    synchronized (stdout) {
                        stdout.append(buf, 0, n);
                    }
                }
            } catch (IOException ignored) {
                // the process ended
            }
        }, "robot-stdout");
        drain.setDaemon(true);
        drain.start();
        return this;
    }

    /** Everything the process printed on stdout after its port line. */
    public String stdout() {
        synchronized (stdout) {
            return stdout.toString();
        }
    }

    public int port() {
        return port;
    }

    public boolean isAlive() {
        return process != null && process.isAlive();
    }

    /** Kills the process as a crash would (SIGKILL) and waits for it to be gone. */
    public void kill() throws InterruptedException {
        if (process != null) {
            process.destroyForcibly();
            process.waitFor(5, TimeUnit.SECONDS);
        }
    }

    @Override
    public void close() throws InterruptedException {
        if (process != null && process.isAlive()) {
            process.destroy();
            if (!process.waitFor(3, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                process.waitFor(3, TimeUnit.SECONDS);
            }
        }
    }
}
