package touchline.transport.nao;


import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Runs the robot side's {@code touchline-nao-sim} on loopback for a test and reads the ports
 * it reports ("rpc listening on port N", "camera listening on port N"). Skips the test (JUnit
 * assumption) when the binary has not been built.
 */
final class RobotSideProcess implements AutoCloseable {

    private static final Pattern RPC = Pattern.compile("rpc listening on port (\\d+)");
    private static final Pattern CAM = Pattern.compile("camera listening on port (\\d+)");

    private final Process process;
    /** Every line the process printed (stdout and stderr), in order. */
    final List<String> output = new java.util.concurrent.CopyOnWriteArrayList<>();
    final int rpcPort;
    final int camPort;

    static Path binary() {
        return new touchline.cli.RobotSideBinaries().of("touchline-nao-sim");
    }

    static void assumeBuilt() {
        touchline.testing.Requirement.robotSide("touchline-nao-sim");
    }

    RobotSideProcess(int rpcPort, int camPort, String... extra) throws Exception {
        assumeBuilt();
        List<String> cmd = new ArrayList<>(List.of(binary().toString(), "--bind", "127.0.0.1",
                "--rpc-port", Integer.toString(rpcPort), "--cam-port", Integer.toString(camPort)));
        cmd.addAll(List.of(extra));
        process = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        CompletableFuture<int[]> ports = new CompletableFuture<>();
        Thread reader = new Thread(() -> {
            int rpc = -1;
            int cam = -1;
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    output.add(line);
                    Matcher m = RPC.matcher(line);
                    if (m.find()) {
                        rpc = Integer.parseInt(m.group(1));
                    }
                    m = CAM.matcher(line);
                    if (m.find()) {
                        cam = Integer.parseInt(m.group(1));
                    }
                    if (rpc > 0 && cam > 0 && !ports.isDone()) {
                        ports.complete(new int[] {rpc, cam});
                    }
                }
            } catch (IOException ignored) {
                // process ended
            }
            ports.completeExceptionally(new IllegalStateException("touchline-nao-sim exited without reporting its ports"));
        }, "nao-sim-output");
        reader.setDaemon(true);
        reader.start();
        int[] p;
        try {
            p = ports.get(10, TimeUnit.SECONDS);
        } catch (Exception e) {
            process.destroyForcibly();
            throw e;
        }
        this.rpcPort = p[0];
        this.camPort = p[1];
    }

    /** SIGSTOP / SIGCONT: a frozen robot whose kernel still holds the TCP connection open. */
    void signal(String name) throws Exception {
        new ProcessBuilder("kill", "-" + name, Long.toString(process.pid())).inheritIO().start().waitFor();
    }

    /**
     * SIGSTOP, then waits until every thread of the process is stopped: {@code kill} returns when
     * the signal is sent, and a thread busy on the other core can still answer a call meanwhile.
     */
    void freeze() throws Exception {
        signal("STOP");
        if (!Poll.until(this::stopped, java.time.Duration.ofSeconds(5))) {
            throw new IllegalStateException("touchline-nao-sim did not stop within 5 s");
        }
    }

    /** Every thread in state T (stopped), read from /proc. */
    private boolean stopped() {
        try (var tasks = Files.list(Path.of("/proc", Long.toString(process.pid()), "task"))) {
            return tasks.allMatch(task -> {
                try {
                    String stat = Files.readString(task.resolve("stat"));
                    return stat.charAt(stat.lastIndexOf(')') + 2) == 'T';
                } catch (IOException e) {
                    return true; // the thread has ended
                }
            });
        } catch (IOException e) {
            return false;
        }
    }

    void kill() throws Exception {
        signal("CONT");
        process.destroyForcibly();
        process.waitFor(5, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws Exception {
        kill();
    }
}
