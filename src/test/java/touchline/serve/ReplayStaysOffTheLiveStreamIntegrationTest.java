package touchline.serve;

import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.Replay;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.record.EnvelopeWriter;
import touchline.record.McapReader;
import touchline.testing.Await;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Issue 38, item 3: a replay runs while the console records and serves its live field. The
 * recorder and the live server take the live stream only, so nothing of the replay (robot 8 of
 * an old match) reaches the new recording's live channels or what the viewers are sent, while
 * the live robot (3) is recorded and served throughout. The recording says each channel's
 * origin ({@code touchline.origin}).
 */
@Tag("integration")
class ReplayStaysOffTheLiveStreamIntegrationTest {

    private static final int LIVE_ROBOT = 3;
    private static final int REPLAYED_ROBOT = 8;
    private final FrameCodec frames = new FrameCodec();

    private static Fumanoid.Message status(int robot, int battery) {
        return Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setRobotName("robot" + robot).setBatteryPercent(battery).setTeamID(13)
                        .build()).build();
    }

    private Envelope envelope(long time, Fumanoid.Message m, String kind) {
        return new Envelope(time, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 40000 + m.getRobotID()),
                m.getRobotID(), kind, m, frames.encode(Framing.LENGTH_PREFIX, m.toByteArray()), null);
    }

    /** An old match: robot 8's statuses and debug texts. */
    private void writeOldMatch(Path file) throws Exception {
        try (EnvelopeWriter w = new EnvelopeWriter(file, EnvelopeWriter.Options.defaults())) {
            for (int i = 0; i < 50; i++) {
                long t = 1_000_000_000_000L + i * 20_000L;
                w.write(envelope(t, status(REPLAYED_ROBOT, 90 - i), "status"));
                w.write(envelope(t + 1, Fumanoid.Message.newBuilder().setRobotID(REPLAYED_ROBOT).setExtension(
                        Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("demo.text").setText("old " + i)
                                .build()).build(), "debugText"));
            }
        }
    }

    private void sendLive(DatagramSocket robot, int port, int battery) throws Exception {
        byte[] d = frames.encode(Framing.LENGTH_PREFIX, status(LIVE_ROBOT, battery).toByteArray());
        robot.send(new DatagramPacket(d, d.length, InetAddress.getLoopbackAddress(), port));
    }

    private static boolean replayedRobots(String topic, Map<String, String> metadata) {
        return topic.startsWith("/robot/" + REPLAYED_ROBOT + "/")
                || String.valueOf(REPLAYED_ROBOT).equals(metadata.get("touchline.robot"));
    }

    private static int battery(JSONObject channel, byte[] payload) {
        try {
            com.google.protobuf.DynamicMessage m = FoxgloveTestClient.decode(channel, payload);
            return ((Number) m.getField(m.getDescriptorForType().findFieldByName("batteryPercent"))).intValue();
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void aReplayWhileRecordingAndServingReachesNeitherTheRecordingsLiveChannelsNorTheViewers(@TempDir Path dir)
            throws Exception {
        Path oldMatch = dir.resolve("old-match.mcap");
        writeOldMatch(oldMatch);
        Path recorded = dir.resolve("live.mcap");
        try (Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                     .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
             Serving serving = new Serving(ServeConfig.defaults().withPort(0), console.field().kinds(), console.field().clock(),
                     console.field().bus(), console.serving().stateChannels()).start();
             FoxgloveTestClient viewer = new FoxgloveTestClient(serving.server().port());
             DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            console.recordings().start(recorded);
            // subscribed after the recorder: what this sees, the recorder was handed before
            List<Integer> batteries = new java.util.concurrent.CopyOnWriteArrayList<>();
            console.field().bus().subscribe(e -> {
                Fumanoid.Status s = e.extension(Fumanoid.status);
                if (s != null) {
                    batteries.add(s.getBatteryPercent());
                }
            });
            sendLive(robot, console.field().port(), 80);
            JSONObject status = viewer.awaitChannel("/robot/" + LIVE_ROBOT + "/status");
            viewer.subscribe(1, status.getInt("id"));

            Replay replay = console.replays().open(oldMatch);
            assertEquals(100, replay.runFor(Long.MAX_VALUE), "the whole old match played");
            assertTrue(console.field().robots().robot(REPLAYED_ROBOT, Origin.REPLAY).isPresent(), "the views have the replay");

            // the live field goes on beside the replay, recorded and served
            sendLive(robot, console.field().port(), 79);
            Await.until("the live status after the replay reaches the viewer", () -> viewer.dataOf(1).stream()
                    .anyMatch(d -> battery(status, d.payload()) == 79));
            Await.until("and the recorder", () -> batteries.contains(79));
            console.recordings().stop();

            List<JSONObject> advertised = viewer.texts().stream().filter(o -> o.optString("op").equals("advertise"))
                    .flatMap(o -> o.getJSONArray("channels").toList().stream().map(c -> new JSONObject((Map<?, ?>) c)))
                    .toList();
            assertTrue(advertised.stream().anyMatch(c -> c.getString("topic").equals("/robot/" + LIVE_ROBOT + "/status")));
            for (JSONObject c : advertised) {
                JSONObject meta = c.optJSONObject("metadata");
                Map<String, String> m = new java.util.HashMap<>();
                if (meta != null) {
                    meta.keySet().forEach(k -> m.put(k, meta.get(k).toString()));
                }
                assertFalse(replayedRobots(c.getString("topic"), m),
                        "the live server offered a replayed channel: " + c.getString("topic") + " " + m);
            }
        }

        try (McapReader mcap = McapReader.open(recorded)) {
            boolean liveRobotRecorded = false;
            for (McapReader.ChannelInfo c : mcap.channels().values()) {
                String origin = c.metadata().getOrDefault("touchline.origin", "live");
                if (origin.equals("live") && mcap.messages(c.id()) > 0) {
                    assertFalse(replayedRobots(c.topic(), c.metadata()),
                            mcap.messages(c.id()) + " replayed messages on the live channel " + c.topic() + " " + c.metadata());
                }
                liveRobotRecorded |= c.topic().equals("/robot/" + LIVE_ROBOT + "/status") && mcap.messages(c.id()) >= 2
                        && origin.equals("live") && c.metadata().containsKey("touchline.origin");
            }
            assertTrue(liveRobotRecorded, "the live robot is recorded, marked live: " + mcap.channels().values());
        }
    }
}
