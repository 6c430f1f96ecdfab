package touchline.serve;

import com.google.protobuf.DynamicMessage;
import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;

import touchline.proto.Fumanoid;

import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.net.http.HttpClient;
import java.net.http.WebSocketHandshakeException;
import java.util.List;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/**
 * The live server against an independent client from the spec, over real loopback sockets:
 * what robots send arrives at the viewers that asked for it, decoded with the advertised schema.
 */
class FoxgloveServerTest {

    private static String field(DynamicMessage m, String name) {
        return String.valueOf(m.getField(m.getDescriptorForType().findFieldByName(name)));
    }

    @Test
    void aViewerSeesARobotsStatusDecodedWithTheAdvertisedSchema() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            assertEquals("foxglove.websocket.v1", viewer.subprotocol());
            JSONObject info = viewer.serverInfo();
            assertEquals("Touchline", info.getString("name"));
            assertEquals(List.of("time"), info.getJSONArray("capabilities").toList());

            field.send(ServedField.status(3, "ada", 50));
            JSONObject channel = viewer.awaitChannel("/robot/3/status");
            assertEquals("protobuf", channel.getString("encoding"));
            assertEquals("protobuf", channel.getString("schemaEncoding"));
            assertEquals("fumanoid.Status", channel.getString("schemaName"));
            // what another Touchline needs to rebuild the envelopes, beside the fields every viewer reads
            JSONObject meta = channel.getJSONObject("metadata");
            assertEquals("3", meta.getString("touchline.robot"));
            assertEquals("status", meta.getString("touchline.kind"));
            assertEquals("IN", meta.getString("touchline.direction"));
            assertEquals("FUMANOID", meta.getString("touchline.channel"));
            assertEquals("LENGTH_PREFIX", meta.getString("touchline.framing"));
            assertEquals("extension", meta.getString("touchline.served"));
            assertTrue(meta.getString("touchline.peer").startsWith("127.0.0.1:"));

            viewer.subscribe(7, channel.getInt("id"));
            // a status is a robot's state: the newest one comes at once, with the time it was heard
            Await.until("the status heard before subscribing", () -> !viewer.dataOf(7).isEmpty());
            assertEquals("50", field(FoxgloveTestClient.decode(channel, viewer.dataOf(7).get(0).payload()), "batteryPercent"));
            field.send(ServedField.status(3, "ada", 77));
            Await.until("a status for subscription 7", () -> viewer.dataOf(7).size() >= 2);
            FoxgloveTestClient.Data d = viewer.dataOf(7).get(1);
            DynamicMessage status = FoxgloveTestClient.decode(channel, d.payload());
            assertEquals("ada", field(status, "robotName"));
            assertEquals("77", field(status, "batteryPercent"));
            assertEquals("13", field(status, "teamID"));
            assertTrue(d.timeNanos() > 0);
            Await.until("server time", () -> !viewer.times().isEmpty());
            assertEquals(1, field.server().stats().viewers());
        }
    }

    @Test
    void aTeamsOwnTypeLoadedAtRunTimeIsServedWithItsOwnSchema() throws Exception {
        var team = com.google.protobuf.DescriptorProtos.FileDescriptorProto.newBuilder().setName("team.proto")
                .setPackage("team").addDependency("fumanoid.proto")
                .addMessageType(com.google.protobuf.DescriptorProtos.DescriptorProto.newBuilder().setName("TeamBall")
                        .addField(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.newBuilder().setName("x")
                                .setNumber(1).setType(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Type.TYPE_FLOAT)
                                .setLabel(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Label.LABEL_OPTIONAL)))
                .addExtension(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.newBuilder().setName("teamBall")
                        .setNumber(1042).setExtendee(".fumanoid.Message").setTypeName(".team.TeamBall")
                        .setType(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Type.TYPE_MESSAGE)
                        .setLabel(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        var file = com.google.protobuf.Descriptors.FileDescriptor.buildFrom(team,
                new com.google.protobuf.Descriptors.FileDescriptor[]{Fumanoid.getDescriptor()});
        var ballType = file.findMessageTypeByName("TeamBall");
        byte[] ball = DynamicMessage.newBuilder(ballType).setField(ballType.findFieldByName("x"), 1.5f).build().toByteArray();
        Fumanoid.Message fromRobot = Fumanoid.Message.newBuilder().setRobotID(6).setUnknownFields(
                com.google.protobuf.UnknownFieldSet.newBuilder().addField(1042, com.google.protobuf.UnknownFieldSet.Field
                        .newBuilder().addLengthDelimited(com.google.protobuf.ByteString.copyFrom(ball)).build()).build()).build();
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            assertTrue(field.console().field().kinds().add(file).isEmpty());
            field.send(fromRobot);
            JSONObject channel = viewer.awaitChannel("/robot/6/teamBall");
            assertEquals("team.TeamBall", channel.getString("schemaName"));
            viewer.subscribe(1, channel.getInt("id"));
            Await.until("subscribed", () -> field.server().stats().subscriptions() == 1);
            field.send(fromRobot);
            Await.until("the team's ball", () -> !viewer.dataOf(1).isEmpty());
            assertEquals("1.5", field(FoxgloveTestClient.decode(channel, viewer.dataOf(1).get(0).payload()), "x"));
        }
    }

    @Test
    void theNewerSubprotocolNameIsAcceptedToo() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient viewer = new FoxgloveTestClient(URI.create("ws://127.0.0.1:" + field.server().port() + "/"),
                     "foxglove.sdk.v1")) {
            assertEquals("foxglove.sdk.v1", viewer.subprotocol());
            assertEquals("serverInfo", viewer.serverInfo().getString("op"));
        }
    }

    @Test
    void twoViewersReceiveOnlyTheChannelsTheySubscribedTo() throws Exception {
        try (ServedField field = new ServedField();
             FoxgloveTestClient a = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient b = new FoxgloveTestClient(field.server().port())) {
            field.send(ServedField.status(3, "three", 30));
            field.send(ServedField.status(4, "four", 40));
            JSONObject three = a.awaitChannel("/robot/3/status");
            JSONObject four = b.awaitChannel("/robot/4/status");
            a.subscribe(1, three.getInt("id"));
            b.subscribe(1, four.getInt("id"));
            Await.until("both subscribed", () -> field.server().stats().subscriptions() == 2);
            for (int i = 0; i < 20; i++) {
                field.send(ServedField.status(3, "three", i));
                field.send(ServedField.status(4, "four", i));
            }
            Await.until("a has robot 3's statuses", () -> a.data().size() >= 5);
            Await.until("b has robot 4's statuses", () -> b.data().size() >= 5);
            for (FoxgloveTestClient.Data d : a.data()) {
                assertEquals("three", field(FoxgloveTestClient.decode(three, d.payload()), "robotName"));
            }
            for (FoxgloveTestClient.Data d : b.data()) {
                assertEquals("four", field(FoxgloveTestClient.decode(four, d.payload()), "robotName"));
            }

            b.unsubscribe(1);
            Await.until("b unsubscribed", () -> field.server().stats().subscriptions() == 1);
            int bHad = b.data().size();
            field.send(ServedField.status(4, "four", 99));
            field.send(ServedField.status(3, "three", 99));
            Await.until("a has the last status", () -> a.data().stream()
                    .anyMatch(d -> d.payload().length > 0 && decodeQuietly(three, d).contains("99")));
            field.publish(ServedField.status(4, "four", 100), "status"); // the bus delivers synchronously
            assertEquals(bHad, b.data().size(), "nothing after unsubscribing");
        }
    }

    private static String decodeQuietly(JSONObject channel, FoxgloveTestClient.Data d) {
        try {
            return FoxgloveTestClient.decode(channel, d.payload()).toString();
        } catch (Exception e) {
            return "";
        }
    }

    @Tag("slow")
    @Test
    void aViewerThatStopsReadingCostsTheOtherNothingAndGetsTheNewestWhenItReadsAgain() throws Exception {
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withQueueLimit(64));
             FoxgloveTestClient fast = new FoxgloveTestClient(field.server().port());
             FoxgloveTestClient slow = new FoxgloveTestClient(field.server().port())) {
            String filler = "x".repeat(1000);
            field.publish(ServedField.text(5, "demo.text", "0 " + filler), "debugText");
            JSONObject channel = fast.awaitChannel("/robot/5/debugText");
            slow.awaitChannel("/robot/5/debugText");
            fast.subscribe(1, channel.getInt("id"));
            slow.subscribe(1, channel.getInt("id"));
            Await.until("both subscribed", () -> field.server().stats().subscriptions() == 2);
            slow.stopReading();

            int published = 0;
            // Publish in batches, each taken by the fast viewer before the next, until the slow
            // viewer's socket is full and its messages are being replaced by newer ones.
            while (field.server().stats().dropped() == 0) {
                assertTrue(published < 1_000_000, "the stalled viewer never fell behind");
                for (int i = 0; i < 32; i++) { // half the queue: the fast viewer takes a batch without dropping
                    published++;
                    field.publish(ServedField.text(5, "demo.text", published + " " + filler), "debugText");
                }
                int expected = published;
                Await.until("the fast viewer has " + expected + " (has " + fast.data().size() + ")", 5000,
                        () -> fast.data().size() >= expected);
            }
            published++;
            field.publish(ServedField.text(5, "demo.text", published + " last"), "debugText");
            int all = published;
            Await.until("the fast viewer has the last one", () -> fast.data().size() >= all);
            assertEquals(published, fast.data().size(), "the fast viewer got every message, none dropped for it");
            for (int i = 0; i < published; i++) {
                String text = field(FoxgloveTestClient.decode(channel, fast.data().get(i).payload()), "text");
                assertTrue(text.startsWith((i + 1) + " "), "in order: " + i);
            }

            slow.resumeReading();
            Await.until("the slow viewer catches up with the newest", () -> !slow.data().isEmpty()
                    && decodeQuietly(channel, slow.data().get(slow.data().size() - 1)).contains(all + " last"));
            assertTrue(slow.data().size() < published, "the stalled viewer's stale messages were dropped");
            assertTrue(field.server().stats().dropped() >= published - slow.data().size(),
                    "every message the slow viewer did not get is counted as dropped");
        }
    }

    @Test
    void matchModeIsAJsonChannelANewSubscriberGetsAtOnceAndEveryChangeAfter() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            JSONObject channel = viewer.awaitChannel("/touchline/matchMode");
            assertEquals("json", channel.getString("encoding"));
            assertEquals("jsonschema", channel.getString("schemaEncoding"));
            assertEquals("object", new JSONObject(channel.getString("schema")).getString("type"));
            viewer.subscribe(3, channel.getInt("id"));
            Await.until("the current match mode", () -> !viewer.dataOf(3).isEmpty());
            JSONObject first = new JSONObject(new String(viewer.dataOf(3).get(0).payload(), StandardCharsets.UTF_8));
            assertTrue(first.getBoolean("mayConsoleSend"));
            assertFalse(first.getBoolean("playIsOn"));

            field.publish(Fumanoid.Message.newBuilder().setRobotID(2).setExtension(Fumanoid.status,
                    Fumanoid.Status.newBuilder().setGameState("PLAYING").build()).build(), "status");
            Await.until("match mode after the robot reports PLAYING", () -> viewer.dataOf(3).stream()
                    .map(d -> new JSONObject(new String(d.payload(), StandardCharsets.UTF_8)))
                    .anyMatch(o -> o.getBoolean("playIsOn") && !o.getBoolean("mayConsoleSend")
                            && o.getString("notice").contains("PLAYING")));
        }
    }

    @Test
    void theTeamsMessageBudgetIsAJsonChannelOnceTheConsoleGuardsATeam() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            viewer.awaitChannel("/touchline/matchMode");
            Await.until("a few ticks without a guarded team", () -> viewer.times().size() >= 3);
            assertTrue(viewer.channel("/team/budget").isEmpty(), "no budget channel without --team");

            field.console().teamBudget().guard(touchline.model.RuleProfile.named("hsl-2026"), 13,
                    new java.net.InetSocketAddress("127.0.0.1", 0));
            JSONObject channel = viewer.awaitChannel("/team/budget");
            assertEquals("json", channel.getString("encoding"));
            viewer.subscribe(7, channel.getInt("id"));
            Await.until("the budget at once", () -> !viewer.dataOf(7).isEmpty());
            JSONObject first = new JSONObject(new String(viewer.dataOf(7).get(0).payload(), StandardCharsets.UTF_8));
            assertEquals(13, first.getInt("team"));
            assertEquals("HSL 2026", first.getString("profile"));
            assertEquals(0, first.getInt("used"));
            long limit = Long.parseLong(first.getString("limit"));
            assertEquals(limit, first.getLong("left"));

            try (java.net.DatagramSocket robot = new java.net.DatagramSocket(new java.net.InetSocketAddress("127.0.0.1", 0))) {
                byte[] message = "team message".getBytes(StandardCharsets.UTF_8);
                for (int i = 0; i < 3; i++) {
                    robot.send(new java.net.DatagramPacket(message, message.length, java.net.InetAddress.getLoopbackAddress(),
                            field.console().teamBudget().port()));
                }
            }
            // no GameController heard: the state is not known, so the three are heard, not counted
            Await.until("three messages heard", () -> viewer.dataOf(7).stream()
                    .map(d -> new JSONObject(new String(d.payload(), StandardCharsets.UTF_8)))
                    .anyMatch(o -> o.getInt("notCounted") == 3 && o.getInt("used") == 0 && o.getLong("left") == limit
                            && !o.getBoolean("gameControllerHeard")));
        }
    }

    @Test
    void theGameControllersStateIsAJsonChannel() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            JSONObject channel = viewer.awaitChannel("/gc/state");
            assertEquals("json", channel.getString("encoding"));
            field.publishGameState("hl12/04-playing.bin");
            viewer.subscribe(1, channel.getInt("id"));
            Await.until("the last game state at once", () -> !viewer.dataOf(1).isEmpty());
            JSONObject playing = new JSONObject(new String(viewer.dataOf(1).get(0).payload(), StandardCharsets.UTF_8));
            assertEquals("PLAYING", playing.getString("state"));
            assertEquals("gc.hl12", playing.getString("format"));

            field.publishGameState("hl12/06-goal-team13.bin");
            Await.until("the state after the goal", () -> viewer.dataOf(1).size() >= 2);
            JSONObject goal = new JSONObject(new String(viewer.dataOf(1).get(1).payload(), StandardCharsets.UTF_8));
            assertEquals("READY", goal.getString("state"));
            JSONObject team13 = goal.getJSONArray("teams").getJSONObject(0);
            assertEquals(13, team13.getInt("teamNumber"));
            assertEquals(1, team13.getInt("score"));
        }
    }

    @Test
    void debugTextIsAlsoAStandardFoxgloveLogPerRobot() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            field.send(ServedField.text(5, "demo.text", "hello"));
            JSONObject log = viewer.awaitChannel("/robot/5/log");
            assertEquals("foxglove.Log", log.getString("schemaName"));
            assertEquals("protobuf", log.getString("encoding"));
            assertEquals("protobuf", log.getString("schemaEncoding"));
            viewer.subscribe(1, log.getInt("id"));
            Await.until("subscribed", () -> field.server().stats().subscriptions() == 1);
            field.send(ServedField.text(5, "demo.text", "ball seen at 1200 mm"));
            Await.until("the log line", () -> !viewer.dataOf(1).isEmpty());
            // decoded with the schema the server advertised, as Foxglove's Log panel would
            DynamicMessage line = FoxgloveTestClient.decode(log, viewer.dataOf(1).get(0).payload());
            var fields = line.getDescriptorForType();
            assertEquals("ball seen at 1200 mm", line.getField(fields.findFieldByName("message")));
            assertEquals("robot5/demo.text", line.getField(fields.findFieldByName("name")));
            assertEquals("INFO", ((com.google.protobuf.Descriptors.EnumValueDescriptor)
                    line.getField(fields.findFieldByName("level"))).getName());
            DynamicMessage stamp = (DynamicMessage) line.getField(fields.findFieldByName("timestamp"));
            long nanos = viewer.dataOf(1).get(0).timeNanos();
            assertEquals(nanos / 1_000_000_000L, stamp.getField(stamp.getDescriptorForType().findFieldByName("seconds")));
            assertEquals((int) (nanos % 1_000_000_000L), stamp.getField(stamp.getDescriptorForType().findFieldByName("nanos")));
        }
    }

    @Test
    void aRobotsPositionIsAdvertisedForThe3dPanel() throws Exception {
        try (ServedField field = new ServedField(); FoxgloveTestClient viewer = new FoxgloveTestClient(field.server().port())) {
            field.send(Fumanoid.Message.newBuilder().setRobotID(4).setExtension(Fumanoid.status, Fumanoid.Status.newBuilder()
                    .setRobotPosition(Fumanoid.Position.newBuilder().setX(1500).setY(-250).setTheta(0)).build()).build());
            JSONObject tf = viewer.awaitChannel("/tf");
            assertEquals("foxglove.FrameTransforms", tf.getString("schemaName"));
            JSONObject scene = viewer.awaitChannel("/field/scene");
            assertEquals("foxglove.SceneUpdate", scene.getString("schemaName"));
            viewer.subscribe(1, tf.getInt("id"));
            Await.until("subscribed", () -> field.server().stats().subscriptions() == 1);
            field.send(Fumanoid.Message.newBuilder().setRobotID(4).setExtension(Fumanoid.status, Fumanoid.Status.newBuilder()
                    .setRobotPosition(Fumanoid.Position.newBuilder().setX(2000).setY(500).setTheta(0)).build()).build());
            Await.until("the transform", () -> !viewer.dataOf(1).isEmpty());
            String text = FoxgloveTestClient.decode(tf, viewer.dataOf(1).get(0).payload()).toString();
            assertTrue(text.contains("child_frame_id: \"robot4\"") && text.contains("x: 2.0") && text.contains("y: 0.5"), text);
        }
    }

    @Test
    void withATokenOnlyAViewerThatPresentsItMayWatch() throws Exception {
        String token = AccessToken.generate(new java.security.SecureRandom());
        try (ServedField field = new ServedField(ServeConfig.defaults().withPort(0).withToken(token))) {
            int port = field.server().port();
            assertEquals(401, refusal(URI.create("ws://127.0.0.1:" + port + "/")));
            assertEquals(401, refusal(URI.create("ws://127.0.0.1:" + port + "/?token=wrong")));
            assertEquals(2, field.server().stats().refused());
            assertEquals(0, field.server().stats().viewers());
            try (FoxgloveTestClient viewer = new FoxgloveTestClient(URI.create(field.server().url("127.0.0.1")),
                    "foxglove.websocket.v1")) {
                assertEquals("serverInfo", viewer.serverInfo().getString("op"));
                assertEquals(2, field.server().stats().refused());
            }
        }
    }

    private static int refusal(URI uri) throws Exception {
        try {
            HttpClient.newHttpClient().newWebSocketBuilder().subprotocols("foxglove.websocket.v1")
                    .buildAsync(uri, new java.net.http.WebSocket.Listener() { }).get(30, TimeUnit.SECONDS).abort();
            return 101;
        } catch (ExecutionException | CompletionException e) {
            if (e.getCause() instanceof WebSocketHandshakeException h) {
                return h.getResponse().statusCode();
            }
            throw e;
        }
    }

    @Test
    void servingBeyondLoopbackWithoutATokenIsRefusedBeforeAnythingIsBound() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () ->
                new FoxgloveServer(ServeConfig.defaults().withBind("0.0.0.0").withPort(0),
                        new touchline.protocol.MessageKinds(), new touchline.app.SystemClock()));
        assertTrue(e.getMessage().contains("token"), e.getMessage());
    }

    /**
     * Issue 38: making the server binds nothing (its owner calls {@code start()}), so a server
     * made for a port in use is no error until it is started.
     */
    @Test
    void makingTheServerBindsNothingStartingItDoes() throws Exception {
        touchline.protocol.MessageKinds kinds = new touchline.protocol.MessageKinds();
        touchline.app.SystemClock clock = new touchline.app.SystemClock();
        try (FoxgloveServer first = new FoxgloveServer(ServeConfig.defaults().withPort(0), kinds, clock).start();
             FoxgloveServer second = new FoxgloveServer(ServeConfig.defaults().withPort(first.port()), kinds, clock)) {
            assertThrows(IllegalStateException.class, second::port, "a server not started has no port");
            assertThrows(java.net.BindException.class, second::start);
            assertThrows(IllegalStateException.class, first::start, "a server starts once");
        }
    }
}
