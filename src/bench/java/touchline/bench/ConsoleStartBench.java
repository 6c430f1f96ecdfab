package touchline.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.DatagramSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * Issue 14's start budgets: from {@code ./touchline console} to the window (≤ 3 s) and to the first
 * robot's data (≤ 5 s), with three simulated robots already sending to the console's port. The
 * window is the {@code xdotool search --onlyvisible} poll of {@link StartBenchCommand}; the first
 * data is the console's own start mark on standard error ({@code touchline.cli.StartMarks}), timed
 * when the bench reads it. Alternating in the same run: the launcher with class-data sharing (the
 * default) and with {@code TOUCHLINE_CDS=0} (the baseline, as before the archive). With
 * {@code --demo}, then {@code ./touchline demo --insecure} on the built tree the same way (issue 14's
 * "demo ready ≤ 5 s"; it needs the demo's ports free).
 */
final class ConsoleStartBench {

    private final int rounds;
    private final boolean demo;

    ConsoleStartBench(int rounds, boolean demo) {
        this.rounds = rounds;
        this.demo = demo;
    }

    int run() throws Exception {
        int port;
        try (DatagramSocket probe = new DatagramSocket(0)) {
            port = probe.getLocalPort(); // a free port for the console; the robots send to it before it binds
        }
        Path robot = new touchline.cli.RobotSideBinaries().of("touchline-robot");
        List<Process> team = new ArrayList<>();
        try {
            java.nio.file.Path logs = java.nio.file.Files.createTempDirectory("touchline-start-bench");
            System.out.println("the robots' output: " + logs);
            for (int id = 1; id <= 3; id++) {
                team.add(new ProcessBuilder(robot.toString(), "--id", String.valueOf(id),
                        "--team", "13", "--console", "127.0.0.1:" + port, "--port", String.valueOf(24000 + id * 10))
                        .redirectErrorStream(true).redirectOutput(logs.resolve("robot-" + id + ".log").toFile()).start());
            }
            List<String> command = List.of("./touchline", "console", "--port", String.valueOf(port));
            // one start of each first, unmeasured: it trains the archive when the build is new
            start(command, true);
            start(command, false);
            double[][] with = new double[2][rounds];
            double[][] without = new double[2][rounds];
            for (int i = 0; i < rounds; i++) {
                double[] w = start(command, true);
                double[] b = start(command, false);
                with[0][i] = w[0];
                with[1][i] = w[1];
                without[0][i] = b[0];
                without[1][i] = b[1];
                System.out.printf("round %d: CDS window %.2f s, data %.2f s; without CDS window %.2f s, data %.2f s%n",
                        i + 1, w[0], w[1], b[0], b[1]);
            }
            report("to the window", with[0], without[0], 3);
            report("to the first robot's data", with[1], without[1], 5);
        } finally {
            team.forEach(Process::destroy);
        }
        if (demo) {
            // ./touchline demo on a built tree: no build, its own team, window and first data (port 11011)
            double[][] d = new double[2][rounds];
            List<String> command = List.of("./touchline", "demo", "--insecure");
            for (int i = 0; i < rounds; i++) {
                double[] r = start(command, true);
                d[0][i] = r[0];
                d[1][i] = r[1];
                System.out.printf("round %d: ./touchline demo window %.2f s, first robot's data %.2f s%n", i + 1, r[0], r[1]);
            }
            double ready = median(d[0]);
            System.out.printf("./touchline demo ready (window shown): median %.2f s, budget 5 s: %s; first robot's data "
                    + "%.2f s%n", ready, ready <= 5 ? "met" : "MISSED", median(d[1]));
        }
        return 0;
    }

    private static void report(String what, double[] with, double[] without, double budget) {
        double m = median(with);
        double b = median(without);
        System.out.printf("./touchline console %s: median %.2f s (max %.2f s), budget %.0f s: %s; "
                        + "without class-data sharing %.2f s; ratio %.2f%n", what, m,
                Arrays.stream(with).max().orElse(0), budget, m <= budget ? "met" : "MISSED", b, m / b);
    }

    /** Seconds to the window and to the first robot's data of one start; the console is stopped after. */
    private static double[] start(List<String> command, boolean cds) throws Exception {
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().put("TOUCHLINE_CDS", cds ? "1" : "0");
        long t0 = System.nanoTime();
        Process p = pb.start();
        CompletableFuture<Double> data = new CompletableFuture<>();
        List<String> output = java.util.Collections.synchronizedList(new ArrayList<>());
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    output.add(line);
                    if (line.startsWith("touchline: first robot's data")) {
                        data.complete((System.nanoTime() - t0) / 1e9);
                    }
                }
            } catch (IOException e) {
                data.completeExceptionally(e);
            }
            data.completeExceptionally(new IOException("the console ended before the first robot's data"));
        }, "console-start-output");
        reader.setDaemon(true);
        reader.start();
        try {
            double window = StartBenchCommand.windowAfter(p, t0, String.join(" ", command));
            try {
                return new double[] {window, data.get(60, TimeUnit.SECONDS)};
            } catch (java.util.concurrent.TimeoutException e) {
                throw new IOException(String.format(java.util.Locale.ROOT,
                        "no robot's data within 60 s of the start (the window shown after %.2f s)", window), e);
            }
        } catch (IOException e) {
            throw new IOException(e.getMessage() + (cds ? "" : " (TOUCHLINE_CDS=0)") + "; its output:\n"
                    + String.join("\n", output), e);
        } finally {
            StartBenchCommand.stop(p);
        }
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }
}
