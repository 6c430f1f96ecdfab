package touchline.transport.remote;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Envelope;
import touchline.transport.Hold;
import touchline.transport.SendGate;
import touchline.transport.SendResult;
import touchline.testing.Await;
import touchline.testing.Requirement;
import touchline.testing.SimulatedRos2Robot;

import java.net.URI;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import static org.junit.jupiter.api.Assertions.*;

/**
 * A robot's Foxglove bridge against real servers nobody here wrote: the Python Foxglove SDK
 * (foxglove.sdk.v1 only) with ROS 2 CDR channels serialized by {@code mcap_ros2}, a JSON and a
 * protobuf channel; and a {@code foxglove.websocket.v1}-only server made with Python's
 * {@code websockets}.
 */
@Tag("interop")
class BridgeTest {

    private static final int ROBOT = 1001;

    private final List<Envelope> heard = new CopyOnWriteArrayList<>();
    private final AtomicReference<Optional<Hold>> hold = new AtomicReference<>(Optional.empty());
    private final SendGate gate = () -> hold.get();

    private Bridge bridge(String url) {
        return new Bridge("booster-1", URI.create(url), null, ROBOT, () -> 1_000_000L, heard::add, gate,
                Duration.ofMillis(500)).start();
    }

    private Optional<Envelope> on(String topic) {
        return heard.stream().filter(e -> e.kind().equals(topic)).reduce((a, b) -> b);
    }

    @Test
    void theFoxgloveSdkServerIsReadOnItsOwnSubprotocolEveryChannelAsTheRobots() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-1"); Bridge bridge = bridge(robot.url())) {
            Await.until("the ten channels", () -> bridge.status().connection().channels() == 10);
            BridgeStatus s = bridge.status();
            assertEquals("foxglove.sdk.v1", s.subprotocol());
            assertEquals("booster-1", s.serverName());
            assertTrue(bridge.offers("parameters") && bridge.offers("clientPublish"), s.describe());
            Await.until("a protobuf /heading", () -> on("/heading").isPresent());
            Envelope heading = on("/heading").orElseThrow();
            assertEquals(Channel.BRIDGE, heading.channel());
            assertEquals(ROBOT, heading.robotId());
            assertNull(heading.error());
            assertEquals("foxglove.Vector2", heading.message().getDescriptorForType().getFullName());
            assertEquals(1_000_000L, heading.timeMicros(), "time-stamped on the console's clock");
            assertEquals("127.0.0.1:" + robot.port(), heading.peerText());
        }
    }

    @Test
    void ros2AndJsonChannelsArriveDecodedByTheirDefinitions() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-2"); Bridge bridge = bridge(robot.url())) {
            Await.until("a /pose, a /rosout and a /robot_state", () -> on("/pose").isPresent()
                    && on("/rosout").isPresent() && on("/robot_state").isPresent());
            Envelope pose = on("/pose").orElseThrow();
            assertNull(pose.error(), pose.toString());
            assertEquals("geometry_msgs/msg/PoseStamped", pose.ros().typeName());
            assertTrue(Double.isFinite(pose.ros().number("pose.position.x")));
            assertEquals("map", pose.ros().at("header.frame_id"));
            Envelope log = on("/rosout").orElseThrow();
            assertTrue(String.valueOf(log.ros().at("msg")).startsWith("walking to"), log.ros().toString());
            Envelope state = on("/robot_state").orElseThrow();
            assertEquals("PLAYING", state.ros().at("game_state"));
            assertTrue(state.ros().number("battery.percentage") > 90);
        }
    }

    @Test
    void aParameterSetAndAPublishAreHeldWhileTheGateHoldsAndGoOutAfter() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-3"); Bridge bridge = bridge(robot.url())) {
            Await.until("connected", () -> bridge.status().online() && bridge.offers("parameters"));
            assertTrue(bridge.refreshParameters().isSent());
            Await.until("the parameters", () -> bridge.parameters().size() == 3);
            assertEquals(0.3, ((Number) param(bridge, "walk.speed").value()).doubleValue());
            assertTrue(param(bridge, "debug.draw_ball").isBool());

            hold.set(Optional.of(Hold.untilPlayStops("match mode, PLAYING")));
            SendResult set = bridge.setParameter("debug.draw_ball", true);
            SendResult publish = bridge.publish("/say", "std_msgs/msg/String", "{\"data\":\"hello\"}");
            assertEquals(SendResult.Outcome.HELD, set.outcome());
            assertEquals("match mode, PLAYING; goes out when play stops", set.reason());
            assertEquals(SendResult.Outcome.HELD, publish.outcome());
            assertEquals(2, bridge.held().size());
            assertEquals(0, bridge.sendHeld(), "still held while the gate holds");
            assertTrue(bridge.refreshParameters().isSent(), "reading passes no gate");
            Await.until("the parameters again", () -> bridge.parametersVersion() >= 2);
            assertEquals(false, param(bridge, "debug.draw_ball").value(), "nothing went out during play");
            assertFalse(robot.heard().contains("client published"), robot.heard());

            hold.set(Optional.empty());
            assertEquals(2, bridge.sendHeld());
            assertTrue(bridge.held().isEmpty());
            Await.until("the robot's new value", () -> Boolean.TRUE.equals(param(bridge, "debug.draw_ball").value()));
            Await.until("the robot heard the publish", () -> robot.heard().contains("{\"data\":\"hello\"}"));
            assertTrue(robot.heard().contains("client advertised /say (json)"), robot.heard());

            hold.set(Optional.of(Hold.always("viewing a remote Touchline: commands are off")));
            SendResult refused = bridge.setParameter("debug.draw_ball", false);
            assertEquals(SendResult.Outcome.FAILED, refused.outcome(), "a gate shut for good refuses, holds nothing");
            assertEquals("viewing a remote Touchline: commands are off", refused.reason());
            assertTrue(bridge.held().isEmpty());
        }
    }

    @Test
    void aCdrPublishIsWrittenByTheTypesDefinitionHeldDuringPlayAndReadByTheRobotsMcapRos2() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-4"); Bridge bridge = bridge(robot.url())) {
            // the robot takes json and cdr and advertises /pose as a ros2msg PoseStamped: a goal pose goes as CDR
            Await.until("the ten channels", () -> bridge.status().connection().channels() == 10
                    && bridge.offers("clientPublish"));
            hold.set(Optional.of(Hold.untilPlayStops("match mode, PLAYING")));
            String goal = "{\"header\":{\"frame_id\":\"field\"},\"pose\":{\"position\":{\"x\":1.5,\"y\":-0.5},"
                    + "\"orientation\":{\"w\":1.0}}}";
            SendResult publish = bridge.publish("/goal_pose", "geometry_msgs/msg/PoseStamped", goal);
            assertEquals(SendResult.Outcome.HELD, publish.outcome(), publish.describe());
            assertEquals(List.of("/goal_pose (cdr): " + goal), bridge.held());
            assertEquals(0, bridge.sendHeld(), "still held while the gate holds");

            SendResult wrong = bridge.publish("/goal_pose", "geometry_msgs/msg/PoseStamped", "{\"pose\":{\"heading\":1}}");
            assertEquals(SendResult.Outcome.FAILED, wrong.outcome(), "values that do not fit are refused, not held");
            assertEquals("geometry_msgs/msg/PoseStamped: geometry_msgs/msg/Pose has no field pose.heading", wrong.reason());
            assertEquals(1, bridge.held().size());
            assertFalse(robot.heard().contains("client advertised /goal_pose"), robot.heard());

            hold.set(Optional.empty());
            assertEquals(1, bridge.sendHeld());
            Await.until("the robot read the goal pose", () -> robot.heard().contains("(cdr) {\"header\": {\"frame_id\": "
                    + "\"field\", \"stamp\": {\"nanosec\": 0, \"sec\": 0}}, \"pose\": {\"orientation\": {\"w\": 1.0, "
                    + "\"x\": 0.0, \"y\": 0.0, \"z\": 0.0}, \"position\": {\"x\": 1.5, \"y\": -0.5, \"z\": 0.0}}}"));
            assertTrue(robot.heard().contains("client advertised /goal_pose (cdr)"), robot.heard());
            assertTrue(bridge.status().lastCommand().startsWith("/goal_pose (cdr): "), bridge.status().lastCommand());
        }
    }

    @Test
    void serviceAnswersAreKeptCdrDecodedByTheResponseDefinitionJsonAsSentAndFailuresWithTheirReason() throws Exception {
        try (SimulatedRos2Robot robot = new SimulatedRos2Robot("booster-5"); Bridge bridge = bridge(robot.url())) {
            Await.until("the three services", () -> bridge.services().size() == 3);
            for (String service : List.of("/booster-5/check", "/booster-5/say", "/booster-5/kick")) {
                SendResult call = bridge.callService(service, "{}");
                assertTrue(call.isSent(), service + ": " + call.describe());
            }
            Await.until("three answers", () -> bridge.serviceAnswers().size() == 3);
            assertEquals("/booster-5/check #1: {success: true, message: \"all joints ready\"}", answer(bridge,
                    "/booster-5/check").describe(), "CDR, decoded by the advertised Trigger_Response");
            ServiceAnswer say = answer(bridge, "/booster-5/say");
            assertTrue(say.ok());
            assertEquals("{\"success\": true, \"message\": \"said\"}", say.text(), "JSON, as the robot sent it");
            ServiceAnswer kick = answer(bridge, "/booster-5/kick");
            assertFalse(kick.ok());
            assertTrue(kick.describe().startsWith("/booster-5/kick #3 failed: ") && kick.text().contains("no ball in reach"),
                    kick.describe());
        }
    }

    private static ServiceAnswer answer(Bridge b, String service) {
        return b.serviceAnswers().stream().filter(a -> a.service().equals(service)).findFirst().orElseThrow();
    }

    private static Bridge.Parameter param(Bridge b, String name) {
        return b.parameters().stream().filter(p -> p.name().equals(name)).findFirst().orElseThrow();
    }

    private static final String WEBSOCKET_V1_SERVER = """
            import asyncio, json, struct, sys
            import websockets
            async def serve(ws):
                await ws.send(json.dumps({"op": "serverInfo", "name": "old-bridge", "capabilities": []}))
                await ws.send(json.dumps({"op": "advertise", "channels": [
                    {"id": 7, "topic": "/battery", "encoding": "json", "schemaName": "", "schema": ""},
                    {"id": 8, "topic": "/scan", "encoding": "flatbuffer", "schemaName": "Scan", "schema": ""}]}))
                sub = json.loads(await ws.recv())["subscriptions"][0]["id"]
                while True:
                    await ws.send(struct.pack("<BIQ", 1, sub, 5) + json.dumps({"percentage": 77}).encode())
                    await asyncio.sleep(0.05)
            async def main():
                async with websockets.serve(serve, "127.0.0.1", 0, subprotocols=["foxglove.websocket.v1"]) as server:
                    print("listening on port %d" % server.sockets[0].getsockname()[1], flush=True)
                    await asyncio.Future()
            asyncio.run(main())
            """;

    @Test
    void anOlderServerOnFoxgloveWebsocketV1IsReadToo() throws Exception {
        Requirement.require(pythonHasWebsockets(), "python3 cannot import websockets (pip install websockets)");
        try (var server = touchline.testing.RobotProcess.of(List.of("python3", "-c", WEBSOCKET_V1_SERVER)).start();
             Bridge bridge = bridge("ws://127.0.0.1:" + server.port() + "/")) {
            Await.until("a /battery", () -> on("/battery").isPresent());
            BridgeStatus s = bridge.status();
            assertEquals("foxglove.websocket.v1", s.subprotocol());
            assertEquals("old-bridge", s.serverName());
            assertEquals(1, s.connection().channels(), "the flatbuffer channel is not subscribed");
            assertEquals(1, s.connection().unusable());
            assertTrue(s.connection().problem().contains("flatbuffer"), s.connection().problem());
        }
    }

    private static boolean pythonHasWebsockets() {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import websockets").start();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (Exception e) {
            return false;
        }
    }
}
