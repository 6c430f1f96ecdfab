package touchline.app.bridges;

import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;
import touchline.model.RosMapping;

import java.io.IOException;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A team of ROS 2 robots in one file, so one command opens them all ({@code console --ros-team
 * FILE}, {@code listen --ros-team FILE}); {@code samples/ros2-team.json}:
 * <pre>
 * { "robots": [ { "name": "booster-1", "url": "ws://10.0.0.11:8765/" }, … ],
 *   "mapping": { "battery./power": "level", "pose": "/localization/pose" } }
 * </pre>
 * {@code mapping} (optional) is the {@link RosMapping} for topics Touchline cannot tell by type.
 */
public record TeamFile(List<BridgeAddress> robots, RosMapping mapping) {

    /** The team in {@code file}; IOException in words (with the file's name) when it cannot be used. */
    public static TeamFile read(Path file) throws IOException {
        try {
            return parse(Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException | IllegalArgumentException | JSONException e) {
            throw new IOException(file + ": " + e.getMessage(), e);
        }
    }

    static TeamFile parse(String text) throws IOException {
        JSONObject o = new JSONObject(text);
        JSONArray list = o.optJSONArray("robots");
        if (list == null || list.isEmpty()) {
            throw new IllegalArgumentException("no \"robots\": a list of {\"name\": …, \"url\": \"ws://…\"}");
        }
        List<BridgeAddress> robots = new ArrayList<>();
        for (int i = 0; i < list.length(); i++) {
            JSONObject r = list.optJSONObject(i);
            if (r == null || !r.has("url")) {
                throw new IllegalArgumentException("robot " + (i + 1) + " has no \"url\"");
            }
            robots.add(BridgeAddress.of(r.optString("name", ""), r.getString("url")));
        }
        JSONObject m = o.optJSONObject("mapping");
        StringBuilder props = new StringBuilder();
        if (m != null) {
            for (String k : m.keySet()) {
                props.append(k.replace(":", "\\:").replace("=", "\\=")).append('=').append(m.get(k)).append('\n');
            }
        }
        return new TeamFile(List.copyOf(robots), m == null ? RosMapping.NONE : RosMapping.parse(new StringReader(
                props.toString())));
    }
}
