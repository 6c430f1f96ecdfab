package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONObject;
import org.junit.jupiter.api.Test;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/**
 * A robot's service answers from bytes a server might send, good and bad: each becomes an
 * answer the user reads (never an exception), and only the newest are kept. The real SDK
 * server's answers are in {@link BridgeTest}.
 */
class BridgeServicesTest {

    private static final String CHECK = "{\"id\":4,\"name\":\"/b/check\",\"type\":\"std_srvs/srv/Trigger\","
            + "\"request\":{\"encoding\":\"cdr\",\"schemaName\":\"std_srvs/srv/Trigger_Request\",\"schemaEncoding\":\"ros2msg\","
            + "\"schema\":\"\"},\"response\":{\"encoding\":\"cdr\",\"schemaName\":\"std_srvs/srv/Trigger_Response\","
            + "\"schemaEncoding\":\"ros2msg\",\"schema\":\"bool success\\nstring message\\n\"}}";

    private static BridgeServices services() {
        BridgeServices s = new BridgeServices();
        s.advertised(new JSONArray().put(new JSONObject(CHECK)));
        return s;
    }

    /** A response (after its opcode): service id, call id, encoding, payload. */
    private static ByteBuffer response(int service, int call, String encoding, byte[] payload) {
        byte[] e = encoding.getBytes(StandardCharsets.US_ASCII);
        return ByteBuffer.allocate(12 + e.length + payload.length).order(ByteOrder.LITTLE_ENDIAN).putInt(service)
                .putInt(call).putInt(e.length).put(e).put(payload).flip();
    }

    private static String last(BridgeServices s) {
        List<ServiceAnswer> a = s.answers();
        return a.get(a.size() - 1).describe();
    }

    @Test
    void aRequestIsWrittenInTheEncodingTheServiceAsksAndItsResponseDecodedByItsDefinition() {
        BridgeServices s = services();
        Outgoing call = s.call("/b/check", "{}", new JSONObject().put("supportedEncodings", new JSONArray().put("json")));
        byte[] bytes = assertInstanceOf(Outgoing.Ready.class, call, call.toString()).payload();
        ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(2, b.get());
        assertEquals(4, b.getInt(), "the service's id");
        assertEquals(1, b.getInt(), "the first call");
        assertEquals(3, b.getInt());
        b.position(b.position() + 3);
        assertEquals(ByteBuffer.wrap(new byte[]{0, 1, 0, 0, 0}), b.slice(), "an empty CDR request: its one placeholder byte");

        s.response(response(4, 1, "cdr", new byte[]{0, 1, 0, 0, 1, 0, 0, 0, 3, 0, 0, 0, 'o', 'k', 0}));
        assertEquals("/b/check #1: {success: true, message: \"ok\"}", last(s));
    }

    @Test
    void badResponsesAreAnswersThatSayWhatWasWrong() {
        BridgeServices s = services();
        s.response(ByteBuffer.wrap(new byte[]{4, 0, 0}));
        assertEquals("a service #0 failed: a response of 3 bytes, too short for its header", last(s));
        s.response(ByteBuffer.allocate(12).order(ByteOrder.LITTLE_ENDIAN).putInt(4).putInt(2).putInt(1 << 30).flip());
        assertEquals("/b/check #2 failed: a response whose encoding claims 1073741824 bytes of 0", last(s));
        s.response(response(4, 3, "cdr", new byte[]{0, 1, 0, 0, 1, 0, 0, 0, 99, 0, 0, 0}));
        assertEquals("/b/check #3 failed: the response does not decode: message: a string of 99 bytes but 0 bytes are left",
                last(s));
        s.response(response(9, 4, "cdr", new byte[]{0, 1, 0, 0}));
        assertEquals("service 9 #4: 4 bytes of CDR (no response definition)", last(s));
        s.response(response(4, 5, "flatbuffer", new byte[7]));
        assertEquals("/b/check #5: 7 bytes of flatbuffer", last(s));
        s.failure(new JSONObject().put("op", "serviceCallFailure").put("serviceId", 4).put("callId", 6)
                .put("message", "knee too hot"));
        assertEquals("/b/check #6 failed: knee too hot", last(s));
        for (int i = 0; i < BridgeServices.MAX_ANSWERS + 5; i++) {
            s.response(response(4, 100 + i, "json", "{}".getBytes(StandardCharsets.UTF_8)));
        }
        assertEquals(BridgeServices.MAX_ANSWERS, s.answers().size(), "only the newest are kept");
        assertEquals("/b/check #136: {}", last(s));
        assertInstanceOf(Outgoing.Refused.class, s.call("/b/gone", "{}", new JSONObject()));
    }
}
