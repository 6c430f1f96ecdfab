package touchline.bench.serve;

import org.json.JSONArray;
import org.json.JSONObject;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

/**
 * A viewer for the benchmark (the JDK's WebSocket client): subscribes to every channel as it
 * is advertised, counts the message frames it receives and how long each took from being
 * published (the frame's receive timestamp) to arriving; {@link #stopReading} makes it one that
 * stops reading.
 */
final class BenchViewer implements AutoCloseable {

    private final LongAdder messages = new LongAdder();
    private final AtomicInteger nextSubscription = new AtomicInteger();
    private final WebSocket ws;
    private final java.util.List<Long> latencies = new java.util.ArrayList<>();
    /** The same for the Foxglove standard channels alone (made by the server's converter thread). */
    private final java.util.List<Long> standardLatencies = new java.util.ArrayList<>();
    /** And for the other channels (the robots' own messages, straight from the publishing thread). */
    private final java.util.List<Long> directLatencies = new java.util.ArrayList<>();
    /** Subscription ids of the standard channels ({@code foxglove.*} schemas). */
    private final java.util.Set<Integer> standard = java.util.concurrent.ConcurrentHashMap.newKeySet();
    private final touchline.transport.MicrosClock clock;
    private volatile boolean reading = true;
    /** Messages logged before this time (a state's newest value sent at subscribing) are counted, not timed. */
    private volatile long timedFromMicros = Long.MAX_VALUE;

    BenchViewer(int port, touchline.transport.MicrosClock clock) throws Exception {
        this.clock = clock;
        ws = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols("foxglove.websocket.v1")
                .buildAsync(URI.create("ws://127.0.0.1:" + port + "/"), new WebSocket.Listener() {
                    private final StringBuilder text = new StringBuilder();

                    @Override
                    public CompletionStage<?> onText(WebSocket w, CharSequence part, boolean last) {
                        text.append(part);
                        if (last) {
                            subscribeAll(w, new JSONObject(text.toString()));
                            text.setLength(0);
                        }
                        more(w);
                        return null;
                    }

                    @Override
                    public CompletionStage<?> onBinary(WebSocket w, ByteBuffer data, boolean last) {
                        if (last && data.remaining() >= 13 && data.get(0) == 1) {
                            messages.increment();
                            ByteBuffer le = data.order(java.nio.ByteOrder.LITTLE_ENDIAN);
                            long sentMicros = le.getLong(5) / 1000;
                            if (sentMicros >= timedFromMicros) {
                                long latency = clock.nowMicros() - sentMicros;
                                synchronized (latencies) {
                                    latencies.add(latency);
                                    (standard.contains(le.getInt(1)) ? standardLatencies : directLatencies).add(latency);
                                }
                            }
                        }
                        more(w);
                        return null;
                    }
                }).get(30, TimeUnit.SECONDS);
    }

    private void subscribeAll(WebSocket w, JSONObject op) {
        if (!op.optString("op").equals("advertise")) {
            return;
        }
        JSONArray subs = new JSONArray();
        JSONArray channels = op.getJSONArray("channels");
        for (int i = 0; i < channels.length(); i++) {
            int id = nextSubscription.getAndIncrement();
            if (channels.getJSONObject(i).optString("schemaName").startsWith("foxglove.")) {
                standard.add(id);
            }
            subs.put(new JSONObject().put("id", id).put("channelId", channels.getJSONObject(i).getInt("id")));
        }
        if (!subs.isEmpty()) {
            w.sendText(new JSONObject().put("op", "subscribe").put("subscriptions", subs).toString(), true);
        }
    }

    private void more(WebSocket w) {
        if (reading) {
            w.request(1);
        }
    }

    /** Times every message logged from now on (what came before is a state sent at subscribing, not a delay). */
    void timeFromNow() {
        timedFromMicros = clock.nowMicros();
    }

    void stopReading() {
        reading = false;
    }

    long messages() {
        return messages.sum();
    }

    /** Microseconds from publishing to receiving, the {@code q} quantile (0..1) of every message so far; -1 when none. */
    long latencyQuantile(double q) {
        return quantile(latencies, q);
    }

    /** The same for the standard channels' messages alone. */
    long standardLatencyQuantile(double q) {
        return quantile(standardLatencies, q);
    }

    /** The same for the other channels' messages alone. */
    long directLatencyQuantile(double q) {
        return quantile(directLatencies, q);
    }

    private long quantile(java.util.List<Long> of, double q) {
        synchronized (latencies) {
            if (of.isEmpty()) {
                return -1;
            }
            java.util.List<Long> sorted = new java.util.ArrayList<>(of);
            java.util.Collections.sort(sorted);
            return sorted.get((int) Math.min(sorted.size() - 1, Math.floor(q * sorted.size())));
        }
    }

    @Override
    public void close() {
        ws.abort();
    }
}
