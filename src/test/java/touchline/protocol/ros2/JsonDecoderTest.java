package touchline.protocol.ros2;

import org.junit.jupiter.api.Test;

import java.nio.charset.StandardCharsets;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

class JsonDecoderTest {

    private final JsonDecoder decoder = new JsonDecoder("foxglove.PoseInFrame");

    private DecodeResult decode(String json) {
        return decoder.decode(json.getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void aJsonObjectIsTheSameTree() {
        DecodeResult r = decode("{\"timestamp\": {\"sec\": 3, \"nsec\": 5}, \"frame_id\": \"map\","
                + " \"pose\": {\"position\": {\"x\": 1.5, \"y\": -2, \"z\": 0}}, \"ok\": true, \"gone\": null,"
                + " \"joints\": [0.5, 1, {\"k\": 2}]}");
        RosMessage m = assertInstanceOf(DecodeResult.Decoded.class, r, r.toString()).message();
        assertEquals("foxglove.PoseInFrame", m.typeName());
        assertEquals(3L, m.at("timestamp.sec"));
        assertEquals("map", m.get("frame_id"));
        assertEquals(1.5, m.number("pose.position.x"));
        assertEquals(-2.0, m.number("pose.position.y"));
        assertEquals(1.0, m.number("ok"));
        assertEquals(null, m.get("gone"));
        assertArrayEquals(new Object[]{0.5, 1L}, java.util.Arrays.copyOf((Object[]) m.get("joints"), 2));
        assertEquals(2.0, m.number("joints[2].k"));
        assertEquals(List.of("joints[0]", "joints[1]", "joints[2].k", "ok", "pose.position.x", "pose.position.y",
                "pose.position.z", "timestamp.nsec", "timestamp.sec"), m.numericPaths());
    }

    @Test
    void badJsonIsAnErrorValue() {
        assertEquals(new DecodeResult.Undecodable("the JSON message is not an object"), decode("[1, 2]"));
        assertEquals(new DecodeResult.Undecodable("text after the JSON object"), decode("{} {}"));
        assertInstanceOf(DecodeResult.Undecodable.class, decode("{\"a\": "));
        assertInstanceOf(DecodeResult.Undecodable.class, decode(""));
        assertEquals(new DecodeResult.Undecodable("the JSON message nests deeper than 32 levels"),
                decode("{\"a\":".repeat(40) + "1" + "}".repeat(40)));
        assertEquals(new DecodeResult.Undecodable("the JSON message nests deeper than 32 levels"),
                decode("{\"a\":" + "[".repeat(40) + "]".repeat(40) + "}"));
    }
}
