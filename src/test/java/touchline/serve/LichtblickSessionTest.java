package touchline.serve;

import org.json.JSONArray;
import org.json.JSONObject;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;

import java.util.ArrayList;
import java.util.Base64;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

/**
 * What Lichtblick's Foxglove WebSocket player does on a connection, as its sources do it
 * (lichtblick-suite/lichtblick, packages/suite-base/src/players/FoxgloveWebSocketPlayer, with
 * the {@code @foxglove/ws-protocol} client it uses): Lichtblick itself cannot run here, so this
 * client replays its ops. It asks for {@code foxglove.websocket.v1}; reads the capabilities
 * (an array: with only {@code time} it sends no parameter, connection-graph or publish ops);
 * parses each advertised channel (protobuf with a base64 schema, JSON with a JSON schema;
 * anything else it marks unsupported) and refuses two channels on one topic; subscribes under
 * its own ids counted from 0, one channel per op, and reads each message by that id;
 * unsubscribes and subscribes again under a new id; and a Lichtblick that has seen a richer
 * server may still ask for parameters or the connection graph: refused with a status, the
 * connection goes on.
 */
class LichtblickSessionTest {

    @Test
    void aLichtblickSessionIsServed() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient lichtblick = new FoxgloveTestClient(field.server().port())) {
            assertEquals("foxglove.websocket.v1", lichtblick.subprotocol());
            JSONObject info = lichtblick.serverInfo();
            assertTrue(info.get("capabilities") instanceof JSONArray);
            assertEquals(List.of("time"), info.getJSONArray("capabilities").toList(),
                    "no capability that makes Lichtblick send ops this server refuses");
            assertTrue(info.get("supportedEncodings") instanceof JSONArray);

            field.send(ServedField.status(3, "ada", 50));
            field.send(ServedField.text(3, "demo.text", "hello"));
            field.publishGameState("hl12/04-playing.bin"); // heard as bytes: a channel only another Touchline reads
            JSONObject status = lichtblick.awaitChannel("/robot/3/status");
            JSONObject log = lichtblick.awaitChannel("/robot/3/log");
            JSONObject matchMode = lichtblick.awaitChannel("/touchline/matchMode");

            List<JSONObject> advertised = new ArrayList<>();
            lichtblick.texts().stream().filter(o -> o.optString("op").equals("advertise"))
                    .forEach(o -> o.getJSONArray("channels").forEach(c -> advertised.add((JSONObject) c)));
            Set<String> topics = new HashSet<>();
            for (JSONObject c : advertised) {
                assertTrue(topics.add(c.getString("topic")), "one channel per topic: " + c.getString("topic"));
                assertTrue(parsesAsLichtblickDoes(c), "Lichtblick parses " + c.getString("topic") + ": " + c);
            }
            assertTrue(advertised.stream().noneMatch(c -> c.getString("topic").startsWith("/gc/gc.")),
                    "the GameController's packets, bytes without a schema, are not advertised to Lichtblick");
            assertEquals("jsonschema", matchMode.getString("schemaEncoding"));
            assertEquals("foxglove.Log", log.getString("schemaName"));

            // Lichtblick's ids count from 0 and are its own, not the channels' ids; one channel per op
            lichtblick.subscribe(0, status.getInt("id"));
            lichtblick.subscribe(1, log.getInt("id"));
            lichtblick.subscribe(2, matchMode.getInt("id"));
            Await.until("the newest status and match mode at once",
                    () -> !lichtblick.dataOf(0).isEmpty() && !lichtblick.dataOf(2).isEmpty());
            field.send(ServedField.text(3, "demo.text", "again"));
            Await.until("the log under subscription 1", () -> !lichtblick.dataOf(1).isEmpty());
            assertTrue(FoxgloveTestClient.decode(log, lichtblick.dataOf(1).get(0).payload()).toString().contains("again"));
            assertTrue(new String(lichtblick.dataOf(2).get(0).payload(), java.nio.charset.StandardCharsets.UTF_8)
                    .startsWith("{"), "match mode is JSON");

            // a panel closed, another opened on the same topic: unsubscribe, subscribe under a new id
            lichtblick.unsubscribe(0);
            lichtblick.subscribe(3, status.getInt("id"));
            Await.until("the status again under subscription 3", () -> !lichtblick.dataOf(3).isEmpty());
            int underZero = lichtblick.dataOf(0).size();
            field.send(ServedField.status(3, "ada", 51));
            Await.until("the new status under 3", () -> lichtblick.dataOf(3).size() >= 2);
            assertEquals(underZero, lichtblick.dataOf(0).size(), "nothing under the cancelled id");

            // ops Lichtblick sends to servers with those capabilities: refused, said, and nothing else happens
            long badBefore = field.server().stats().badRequests();
            lichtblick.send("{\"op\":\"getParameters\",\"parameterNames\":[],\"id\":\"get-all-params\"}");
            lichtblick.send("{\"op\":\"subscribeParameterUpdates\",\"parameterNames\":[\"a\"]}");
            lichtblick.send("{\"op\":\"subscribeConnectionGraph\"}");
            lichtblick.send("{\"op\":\"fetchAsset\",\"uri\":\"package://robot/model.urdf\",\"requestId\":1}");
            Await.until("four statuses", () -> lichtblick.statuses().size() >= 4);
            for (JSONObject s : lichtblick.statuses()) {
                assertEquals(2, s.getInt("level"));
                assertTrue(s.getString("message").contains("read-only server"), s.toString());
            }
            assertEquals(badBefore + 4, field.server().stats().badRequests());
            field.send(ServedField.text(3, "demo.text", "still here"));
            Await.until("the log goes on", () -> lichtblick.dataOf(1).size() >= 2);
            assertFalse(lichtblick.closed());
        }
    }

    @Test
    void theChannelsOfBytesGoOnlyToAViewerThatAsksForThem() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient touchline = new FoxgloveTestClient(
                     java.net.URI.create("ws://127.0.0.1:" + field.server().port() + "/?raw=1"), "foxglove.websocket.v1");
             FoxgloveTestClient lichtblick = new FoxgloveTestClient(field.server().port())) {
            field.publishGameState("hl12/04-playing.bin");
            field.send(ServedField.status(3, "ada", 50));
            JSONObject gc = touchline.awaitChannel("/gc/gc.hl12");
            assertEquals("application/octet-stream", gc.getString("encoding"));
            lichtblick.awaitChannel("/robot/3/status");
            touchline.awaitChannel("/robot/3/status");
            assertTrue(lichtblick.channel("/gc/gc.hl12").isEmpty(), "not advertised without ?raw=1");
            // and not to be had by guessing its id
            lichtblick.subscribe(9, gc.getInt("id"));
            Await.until("refused", () -> !lichtblick.statuses().isEmpty());
            assertTrue(lichtblick.statuses().get(0).getString("message").contains("unknown channel " + gc.getInt("id")));
            touchline.subscribe(9, gc.getInt("id"));
            Await.until("subscribed", () -> field.server().stats().subscriptions() == 1);
            field.publishGameState("hl12/04-playing.bin");
            Await.until("the packet's bytes", () -> !touchline.dataOf(9).isEmpty());
        }
    }

    /** The encodings Lichtblick's player turns into a parsed channel; the rest it lists as unsupported. */
    private static boolean parsesAsLichtblickDoes(JSONObject c) {
        String encoding = c.getString("encoding");
        String schemaEncoding = c.optString("schemaEncoding", "");
        if (encoding.equals("protobuf") && (schemaEncoding.isEmpty() || schemaEncoding.equals("protobuf"))) {
            return Base64.getDecoder().decode(c.getString("schema")).length > 0 && !c.getString("schemaName").isEmpty();
        }
        if (encoding.equals("json") && (schemaEncoding.isEmpty() || schemaEncoding.equals("jsonschema"))) {
            return new JSONObject(c.getString("schema")).has("type");
        }
        return false;
    }
}
