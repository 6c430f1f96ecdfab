package touchline.record.foxglove;

import org.json.JSONArray;
import org.json.JSONObject;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.Recording;
import touchline.testing.PythonMcap;
import touchline.transport.Envelope;

import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The foxglove export read back by the independent Python {@code mcap} reader and
 * {@code mcap-protobuf-support} decoder (with the schemas the file carries): the standard
 * messages hold what the robots sent, and the recorded channels are all still there.
 */
@Tag("interop")
class FoxgloveExportInteropTest {

    private static final long T0 = 1_760_000_000_000_000L;

    @TempDir
    Path dir;

    private static final String READ = """
            import sys, json, hashlib
            from mcap.reader import make_reader
            from mcap_protobuf.decoder import DecoderFactory
            out = {'battery': None, 'topics': {}, 'log': [], 'camera': [], 'nao': [], 'regions': [], 'frames': [], 'tf': []}
            with open(sys.argv[1], 'rb') as f:
                r = make_reader(f, decoder_factories=[DecoderFactory()])
                for c in r.get_summary().channels.values():
                    out['topics'].setdefault(c.topic, '')
                pb = [c.topic for c in r.get_summary().channels.values() if c.message_encoding == 'protobuf']
                for schema, channel, message, m in r.iter_decoded_messages(topics=pb):
                    out['topics'][channel.topic] = schema.name
                    t = channel.topic
                    if t == '/robot/3/log':
                        out['log'].append([m.message, m.name, m.level, m.timestamp.seconds * 10**9 + m.timestamp.nanos,
                                           message.log_time])
                    elif t == '/robot/3/camera':
                        out['camera'].append([m.format, hashlib.sha256(m.data).hexdigest(), m.frame_id])
                    elif t == '/nao/camera/image':
                        out['nao'].append([m.format, hashlib.sha256(m.data).hexdigest()])
                    elif t == '/robot/3/regions':
                        out['regions'].append([[[p.x, p.y] for p in a.points] for a in m.points]
                                              + [a.type for a in m.points])
                    elif t == '/robot/3/regions/frame':
                        out['frames'].append([m.format, m.frame_id, m.timestamp.seconds, m.timestamp.nanos])
                    elif t == '/robot/3/status':
                        out['battery'] = m.batteryPercent
                    elif t == '/tf':
                        x = m.transforms[0]
                        out['tf'].append([x.child_frame_id, x.translation.x, x.translation.y])
            print(json.dumps(out))
            """;

    @Test
    void pythonReadsTheStandardMessagesWithWhatTheRobotsSent() throws Exception {
        PythonMcap.require("mcap", "mcap_protobuf");
        byte[] jpeg = FoxgloveFixture.jpeg(40, 30);
        byte[] naoJpeg = FoxgloveFixture.jpeg(64, 48);
        List<Envelope> sent = new ArrayList<>();
        List<String> lines = List.of("search ball", "ball seen at 1200 mm, ß ok", "kick, \"now\"");
        for (int i = 0; i < lines.size(); i++) {
            sent.add(FoxgloveFixture.text(T0 + i * 100_000L, 3, "behaviour", lines.get(i)));
        }
        sent.add(FoxgloveFixture.image(T0 + 400_000, 3, Fumanoid.ImageFormat.JPEG, 40, 30, jpeg));
        sent.add(FoxgloveFixture.regions(T0 + 500_000, 3, new int[]{1, 10, 20, 30, 45}, new int[]{3, 0, 0, 5, 6}));
        sent.add(FoxgloveFixture.status(T0 + 600_000, 3, 1500, -250, 0));
        sent.add(FoxgloveFixture.naoFrame(T0 + 700_000, naoJpeg));
        Path export = FoxgloveFixture.recordAndExport(dir, sent);

        JSONObject got = new JSONObject(PythonMcap.run(READ, export).lines().reduce((a, b) -> b).orElseThrow());
        JSONObject topics = got.getJSONObject("topics");
        assertEquals("foxglove.Log", topics.getString("/robot/3/log"));
        assertEquals("foxglove.CompressedImage", topics.getString("/robot/3/camera"));
        assertEquals("foxglove.ImageAnnotations", topics.getString("/robot/3/regions"));
        assertEquals("foxglove.FrameTransforms", topics.getString("/tf"));
        assertEquals("foxglove.SceneUpdate", topics.getString("/field/scene"));
        // the recorded channels stay, moved aside; their topics carry the extension's own type, as served live
        assertEquals("fumanoid.Message", topics.getString("/touchline/robot/3/debugText"));
        assertEquals("fumanoid.DebugText", topics.getString("/robot/3/debugText"));
        assertEquals("fumanoid.Status", topics.getString("/robot/3/status"));
        assertEquals(80, got.getInt("battery")); // a plot's path /robot/3/status.batteryPercent
        assertTrue(topics.has("/nao/camera/frame"), topics.toString());

        JSONArray log = got.getJSONArray("log");
        assertEquals(lines.size(), log.length());
        for (int i = 0; i < lines.size(); i++) {
            JSONArray l = log.getJSONArray(i);
            assertEquals(lines.get(i), l.getString(0));
            assertEquals("robot3/behaviour", l.getString(1));
            assertEquals(2, l.getInt(2)); // INFO
            assertEquals((T0 + i * 100_000L) * 1000, l.getLong(3));
            assertEquals(l.getLong(3), l.getLong(4)); // log time = the message's timestamp
        }
        JSONArray camera = got.getJSONArray("camera").getJSONArray(0);
        assertEquals("jpeg", camera.getString(0));
        assertEquals(sha256(jpeg), camera.getString(1));
        assertEquals(sha256(naoJpeg), got.getJSONArray("nao").getJSONArray(0).getString(1));

        JSONArray regions = got.getJSONArray("regions").getJSONArray(0);
        assertEquals("[[10,20],[30,20],[30,45],[10,45]]", regions.getJSONArray(0).toString().replace(".0", ""));
        assertEquals("[[0,0],[5,0],[5,6],[0,6]]", regions.getJSONArray(1).toString().replace(".0", ""));
        assertEquals(2, regions.getInt(2)); // LINE_LOOP
        JSONArray frame = got.getJSONArray("frames").getJSONArray(0);
        assertEquals("png", frame.getString(0));
        assertEquals("robot3/havimo.region", frame.getString(1));

        JSONArray tf = got.getJSONArray("tf").getJSONArray(0);
        assertEquals("robot3", tf.getString(0));
        assertEquals(1.5, tf.getDouble(1), 1e-6);
    }

    @Test
    void touchlineStillReplaysTheExportAsTheRecording() throws Exception {
        List<Envelope> sent = List.of(FoxgloveFixture.text(T0, 1, "o", "one"), FoxgloveFixture.status(T0 + 10, 1, 1, 2, 0));
        Path export = FoxgloveFixture.recordAndExport(dir, sent);
        try (Recording r = Recording.open(export)) {
            List<Envelope> back = new ArrayList<>();
            Recording.Cursor c = r.cursor(Long.MIN_VALUE);
            for (Envelope e = c.next(); e != null; e = c.next()) {
                back.add(e);
            }
            assertEquals(sent.size(), back.size());
            assertEquals("one", back.get(0).extension(Fumanoid.debugText).getText());
            assertNotNull(back.get(1).extension(Fumanoid.status));
            assertEquals(List.of(), r.problems()); // the standard channels are skipped quietly
        }
    }

    private static String sha256(byte[] data) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(data));
    }
}
