package touchline.serve;

import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import org.json.JSONArray;
import org.json.JSONObject;
import touchline.testing.Await;

import java.io.ByteArrayOutputStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Base64;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

/**
 * A Foxglove WebSocket viewer written from the spec (docs/spec.md of foxglove/ws-protocol)
 * with the JDK's own WebSocket client, sharing no code with the server: it parses the JSON
 * ops, the little-endian binary frames, and decodes payloads with the schema the server
 * advertised. {@link #stopReading()} makes it a viewer whose network stalls.
 */
final class FoxgloveTestClient implements AutoCloseable {

    record Data(int subscriptionId, long timeNanos, byte[] payload) {
    }

    private final List<JSONObject> texts = new CopyOnWriteArrayList<>();
    private final List<Data> data = new CopyOnWriteArrayList<>();
    private final List<Long> times = new CopyOnWriteArrayList<>();
    private final Map<Integer, JSONObject> channels = new java.util.concurrent.ConcurrentHashMap<>();
    private volatile boolean reading = true;
    private volatile boolean closed;
    private final WebSocket ws;

    private final WebSocket.Listener listener = new WebSocket.Listener() {
        private final StringBuilder text = new StringBuilder();
        private final ByteArrayOutputStream binary = new ByteArrayOutputStream();

        @Override
        public CompletionStage<?> onText(WebSocket w, CharSequence part, boolean last) {
            text.append(part);
            if (last) {
                JSONObject o = new JSONObject(text.toString());
                text.setLength(0);
                if (o.optString("op").equals("advertise")) {
                    JSONArray list = o.getJSONArray("channels");
                    for (int i = 0; i < list.length(); i++) {
                        channels.put(list.getJSONObject(i).getInt("id"), list.getJSONObject(i));
                    }
                }
                texts.add(o);
            }
            more(w);
            return null;
        }

        @Override
        public CompletionStage<?> onBinary(WebSocket w, ByteBuffer part, boolean last) {
            byte[] b = new byte[part.remaining()];
            part.get(b);
            binary.writeBytes(b);
            if (last) {
                ByteBuffer m = ByteBuffer.wrap(binary.toByteArray()).order(ByteOrder.LITTLE_ENDIAN);
                binary.reset();
                byte op = m.get();
                if (op == 0x01) {
                    int sub = m.getInt();
                    long t = m.getLong();
                    byte[] payload = new byte[m.remaining()];
                    m.get(payload);
                    data.add(new Data(sub, t, payload));
                } else if (op == 0x02) {
                    times.add(m.getLong());
                }
            }
            more(w);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket w, int status, String reason) {
            closed = true;
            return null;
        }

        @Override
        public void onError(WebSocket w, Throwable error) {
            closed = true;
        }
    };

    private void more(WebSocket w) {
        if (reading) {
            w.request(1);
        }
    }

    FoxgloveTestClient(URI uri, String subprotocol) throws Exception {
        ws = HttpClient.newHttpClient().newWebSocketBuilder().subprotocols(subprotocol)
                .buildAsync(uri, listener).get(30, TimeUnit.SECONDS);
    }

    FoxgloveTestClient(int port) throws Exception {
        this(URI.create("ws://127.0.0.1:" + port + "/"), "foxglove.websocket.v1");
    }

    String subprotocol() {
        return ws.getSubprotocol();
    }

    JSONObject serverInfo() throws InterruptedException {
        Await.until("serverInfo", () -> texts.stream().anyMatch(o -> o.optString("op").equals("serverInfo")));
        return texts.stream().filter(o -> o.optString("op").equals("serverInfo")).findFirst().orElseThrow();
    }

    List<JSONObject> texts() {
        return texts;
    }

    List<JSONObject> statuses() {
        return texts.stream().filter(o -> o.optString("op").equals("status")).toList();
    }

    List<Data> data() {
        return data;
    }

    List<Long> times() {
        return times;
    }

    boolean closed() {
        return closed || ws.isInputClosed();
    }

    Optional<JSONObject> channel(String topic) {
        return channels.values().stream().filter(c -> c.getString("topic").equals(topic)).findFirst();
    }

    JSONObject awaitChannel(String topic) throws InterruptedException {
        Await.until("channel " + topic + " advertised", 5000, () -> channel(topic).isPresent());
        return channel(topic).orElseThrow();
    }

    JSONObject channelById(int id) {
        return channels.get(id);
    }

    void send(String text) {
        ws.sendText(text, true).join();
    }

    void sendPart(String text, boolean last) {
        ws.sendText(text, last).join();
    }

    void sendBinary(ByteBuffer bytes) {
        ws.sendBinary(bytes, true).join();
    }

    void subscribe(int subscriptionId, int channelId) {
        send(new JSONObject().put("op", "subscribe").put("subscriptions",
                new JSONArray().put(new JSONObject().put("id", subscriptionId).put("channelId", channelId))).toString());
    }

    void unsubscribe(int subscriptionId) {
        send(new JSONObject().put("op", "unsubscribe").put("subscriptionIds", new JSONArray().put(subscriptionId)).toString());
    }

    List<Data> dataOf(int subscriptionId) {
        return data.stream().filter(d -> d.subscriptionId() == subscriptionId).toList();
    }

    /** Stops taking messages off the socket: the server's writes back up as over a stalled network. */
    void stopReading() {
        reading = false;
    }

    void resumeReading() {
        reading = true;
        ws.request(1);
    }

    /** Decodes {@code payload} with the schema advertised for {@code channel}, as Foxglove would. */
    static DynamicMessage decode(JSONObject channel, byte[] payload) throws Exception {
        FileDescriptorSet set = FileDescriptorSet.parseFrom(Base64.getDecoder().decode(channel.getString("schema")));
        Map<String, FileDescriptor> built = new HashMap<>();
        for (FileDescriptorProto file : set.getFileList()) { // dependencies come first
            List<FileDescriptor> deps = new ArrayList<>();
            for (String dep : file.getDependencyList()) {
                deps.add(built.get(dep));
            }
            built.put(file.getName(), FileDescriptor.buildFrom(file, deps.toArray(new FileDescriptor[0])));
        }
        String name = channel.getString("schemaName");
        for (FileDescriptor f : built.values()) {
            String pkg = f.getPackage().isEmpty() ? "" : f.getPackage() + ".";
            if (name.startsWith(pkg)) {
                Descriptor d = f.findMessageTypeByName(name.substring(pkg.length()));
                if (d != null) {
                    return DynamicMessage.parseFrom(d, payload);
                }
            }
        }
        throw new AssertionError("schema " + name + " is not in the advertised descriptor set");
    }

    @Override
    public void close() {
        ws.abort();
    }
}
