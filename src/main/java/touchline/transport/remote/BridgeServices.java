package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONObject;
import touchline.protocol.ros2.CdrDecoder;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.DefinitionParser;
import touchline.protocol.ros2.DefinitionResult;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A robot's services as its Foxglove server advertised them, the calls made to them and what
 * came back: each request written in the encoding the service (or the server) takes
 * ({@link ClientEncoding}), each response decoded by the service's response definition when
 * CDR or kept as its JSON text, each failure with the server's reason — the newest
 * {@link #MAX_ANSWERS} kept for the user to see.
 */
final class BridgeServices {

    static final int MAX_ANSWERS = 32;
    /** The longest answer kept, in characters: a response is read by a person, not stored. */
    static final int MAX_TEXT = 2000;

    private final Map<String, JSONObject> byName = new TreeMap<>();
    private final Deque<ServiceAnswer> answers = new ArrayDeque<>();
    private final AtomicInteger calls = new AtomicInteger();

    synchronized List<String> names() {
        return new ArrayList<>(byName.keySet());
    }

    synchronized boolean has(String service) {
        return byName.containsKey(service);
    }

    /** The newest answers, oldest first. */
    synchronized List<ServiceAnswer> answers() {
        return new ArrayList<>(answers);
    }

    synchronized void advertised(JSONArray list) {
        for (int i = 0; list != null && i < list.length(); i++) {
            JSONObject s = list.optJSONObject(i);
            if (s != null && !s.optString("name").isEmpty()) {
                byName.put(s.getString("name"), s);
            }
        }
    }

    synchronized void unadvertised(JSONArray ids) {
        for (int i = 0; ids != null && i < ids.length(); i++) {
            int id = ids.optInt(i, -1);
            byName.values().removeIf(s -> s.optInt("id") == id);
        }
    }

    /** The call message (op 2) for {@code service} with the request typed as {@code json}, or why not. */
    Outgoing call(String service, String json, JSONObject serverInfo) {
        JSONObject s;
        synchronized (this) {
            s = byName.get(service);
        }
        if (s == null) {
            return new Outgoing.Refused("the robot no longer offers " + service);
        }
        JSONObject request = s.optJSONObject("request");
        Outgoing out = new ClientEncoding(serverInfo).write(s.optString("type", service) + "_Request",
                schema(s, "request"), request == null ? "" : request.optString("encoding", ""), json);
        if (!(out instanceof Outgoing.Ready r)) {
            return out;
        }
        byte[] encoding = r.encoding().getBytes(StandardCharsets.US_ASCII);
        byte[] call = ByteBuffer.allocate(13 + encoding.length + r.payload().length).order(ByteOrder.LITTLE_ENDIAN)
                .put((byte) 0x02).putInt(s.optInt("id")).putInt(calls.incrementAndGet()).putInt(encoding.length)
                .put(encoding).put(r.payload()).array();
        return new Outgoing.Ready(r.encoding(), r.schema(), call);
    }

    /**
     * The ROS 2 definition of a service's {@code request} or {@code response}: its own schema
     * object (the SDK's servers), or the older {@code requestSchema}/{@code responseSchema} text
     * (a {@code ros2msg} of {@code TYPE_Request}/{@code TYPE_Response}); null when none.
     */
    private static BridgedSchema schema(JSONObject service, String part) {
        JSONObject o = service.optJSONObject(part);
        if (o != null) {
            BridgedSchema s = new BridgedSchema(o.optString("encoding", ""), o.optString("schemaName", ""),
                    o.optString("schemaEncoding", ""), o.optString("schema", "").getBytes(StandardCharsets.UTF_8));
            return s.isRos2() ? s : null;
        }
        String text = service.optString(part + "Schema", "");
        String type = service.optString("type", "");
        return text.isEmpty() || type.isEmpty() ? null : new BridgedSchema("cdr",
                type + (part.equals("request") ? "_Request" : "_Response"), "ros2msg",
                text.getBytes(StandardCharsets.UTF_8));
    }

    /** A service call response (op 3, after the opcode): service id, call id, encoding, payload. */
    void response(ByteBuffer m) {
        if (m.remaining() < 12) {
            answered(new ServiceAnswer("a service", 0, false, "a response of " + m.remaining()
                    + " bytes, too short for its header"));
            return;
        }
        int serviceId = m.getInt();
        int call = m.getInt();
        int length = m.getInt();
        if (length < 0 || length > m.remaining()) {
            answered(new ServiceAnswer(name(serviceId), call, false, "a response whose encoding claims " + length
                    + " bytes of " + m.remaining()));
            return;
        }
        byte[] e = new byte[length];
        m.get(e);
        String encoding = new String(e, StandardCharsets.US_ASCII);
        byte[] payload = new byte[m.remaining()];
        m.get(payload);
        JSONObject s;
        synchronized (this) {
            s = byName.values().stream().filter(x -> x.optInt("id", -1) == serviceId).findFirst().orElse(null);
        }
        answered(switch (encoding) {
            case "json" -> new ServiceAnswer(name(serviceId), call, true,
                    clip(new String(payload, StandardCharsets.UTF_8)));
            case "cdr" -> cdr(name(serviceId), call, s == null ? null : schema(s, "response"), payload);
            default -> new ServiceAnswer(name(serviceId), call, true, payload.length + " bytes of " + encoding);
        });
    }

    private static ServiceAnswer cdr(String service, int call, BridgedSchema response, byte[] payload) {
        if (response == null) {
            return new ServiceAnswer(service, call, true, payload.length + " bytes of CDR (no response definition)");
        }
        DefinitionResult parsed = new DefinitionParser().parse(response.schemaName(), response.schemaEncoding(),
                new String(response.schemaData(), StandardCharsets.UTF_8));
        if (parsed instanceof DefinitionResult.Refused r) {
            return new ServiceAnswer(service, call, false, "the response definition does not parse: " + r.reason());
        }
        DecodeResult d = new CdrDecoder(((DefinitionResult.Parsed) parsed).definition()).decode(payload);
        return d instanceof DecodeResult.Decoded decoded ? new ServiceAnswer(service, call, true,
                decoded.message().line(MAX_TEXT))
                : new ServiceAnswer(service, call, false, "the response does not decode: "
                        + ((DecodeResult.Undecodable) d).reason());
    }

    /** A {@code serviceCallFailure} op: the call went out, the robot could not answer it. */
    void failure(JSONObject o) {
        answered(new ServiceAnswer(name(o.optInt("serviceId", -1)), o.optInt("callId", 0), false,
                clip(o.optString("message", "no reason given"))));
    }

    private synchronized String name(int serviceId) {
        return byName.values().stream().filter(s -> s.optInt("id", -1) == serviceId).map(s -> s.optString("name"))
                .findFirst().orElse("service " + Integer.toUnsignedString(serviceId));
    }

    private synchronized void answered(ServiceAnswer a) {
        answers.addLast(a);
        while (answers.size() > MAX_ANSWERS) {
            answers.removeFirst();
        }
    }

    private static String clip(String s) {
        return s.length() <= MAX_TEXT ? s : s.substring(0, MAX_TEXT - 1) + "…";
    }
}
