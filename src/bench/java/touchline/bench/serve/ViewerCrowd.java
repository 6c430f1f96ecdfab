package touchline.bench.serve;

import touchline.serve.FoxgloveServer;
import touchline.transport.MicrosClock;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Viewers for a benchmark: {@code count} of them (the JDK's WebSocket client, in this JVM)
 * connected to a live server and subscribed to every channel it advertises, one of them
 * stopping to read when asked. Latency is timed only for messages logged after all of them are
 * subscribed: what a new subscriber gets at once (a state's newest value) is not a delay.
 */
public final class ViewerCrowd implements AutoCloseable {

    private final FoxgloveServer server; // null in a process of its own (main)
    private final List<BenchViewer> viewers = new ArrayList<>();
    private final boolean stalled;

    /**
     * Viewers in a JVM of their own, as viewers on other machines would be (they do not share
     * the console's heap): {@code PORT COUNT}. Connects, says {@code connected}, times from the
     * line {@code go} on standard input, and at its end prints {@link #summary()} and exits.
     */
    public static void main(String[] args) throws Exception {
        MicrosClock clock = new touchline.app.SystemClock();
        ViewerCrowd crowd = new ViewerCrowd(Integer.parseInt(args[0]), Integer.parseInt(args[1]), clock);
        System.out.println("connected");
        java.io.BufferedReader in = new java.io.BufferedReader(new java.io.InputStreamReader(System.in,
                java.nio.charset.StandardCharsets.UTF_8));
        for (String line = in.readLine(); line != null; line = in.readLine()) {
            if (line.equals("go")) {
                crowd.viewers.forEach(BenchViewer::timeFromNow);
            }
        }
        System.out.println(crowd.summary());
        crowd.viewers.forEach(BenchViewer::close);
        System.exit(0);
    }

    private ViewerCrowd(int port, int count, MicrosClock clock) throws Exception {
        this.server = null;
        this.stalled = false;
        for (int i = 0; i < count; i++) {
            viewers.add(new BenchViewer(port, clock));
        }
    }

    /** Connects the viewers and returns once each is subscribed to every channel (or after 30 s). */
    public ViewerCrowd(FoxgloveServer server, int count, boolean stalled, MicrosClock clock) throws Exception {
        this.server = server;
        this.stalled = stalled;
        for (int i = 0; i < count; i++) {
            viewers.add(new BenchViewer(server.port(), clock));
        }
        long wanted = (long) server.stats().channels() * count;
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (server.stats().subscriptions() < wanted && System.nanoTime() < deadline) {
            Thread.sleep(10); // waiting for the viewers' subscriptions to arrive
        }
        if (stalled && !viewers.isEmpty()) {
            viewers.get(0).stopReading();
        }
        viewers.forEach(BenchViewer::timeFromNow);
    }

    /** One line per viewer: messages, latency p50/p99 (all, and the standard channels alone). */
    public void print(String latencyName) {
        for (int i = 0; i < viewers.size(); i++) {
            BenchViewer v = viewers.get(i);
            System.out.printf(Locale.ROOT, "  viewer %d: %d messages, %s p50 %.1f ms p99 %.1f ms (p99 of the robots' own "
                            + "channels %.1f ms, of the standard channels %.1f ms)%s%n", i + 1, v.messages(), latencyName,
                    v.latencyQuantile(0.5) / 1e3, v.latencyQuantile(0.99) / 1e3, v.directLatencyQuantile(0.99) / 1e3,
                    v.standardLatencyQuantile(0.99) / 1e3, stalled && i == 0 ? " (stalled)" : "");
        }
    }

    /** The reading viewers' messages (fewest–most) and p99 (best–worst), in one line. */
    public String summary() {
        List<BenchViewer> reading = stalled && !viewers.isEmpty() ? viewers.subList(1, viewers.size()) : viewers;
        long fewest = reading.stream().mapToLong(BenchViewer::messages).min().orElse(0);
        long most = reading.stream().mapToLong(BenchViewer::messages).max().orElse(0);
        double best = reading.stream().mapToLong(v -> v.latencyQuantile(0.99)).min().orElse(-1) / 1e3;
        double worst = reading.stream().mapToLong(v -> v.latencyQuantile(0.99)).max().orElse(-1) / 1e3;
        return String.format(Locale.ROOT, "%d viewers: %d–%d messages each, latency p99 %.1f–%.1f ms", reading.size(),
                fewest, most, best, worst);
    }

    /** Disconnects every viewer and waits (up to 10 s) until the server has let them go. */
    @Override
    public void close() throws InterruptedException {
        viewers.forEach(BenchViewer::close);
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (server != null && server.stats().viewers() > 0 && System.nanoTime() < deadline) {
            Thread.sleep(10); // the closed viewers leave before the next baseline
        }
    }
}
