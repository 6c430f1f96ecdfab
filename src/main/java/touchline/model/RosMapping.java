package touchline.model;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The user's word on a ROS 2 robot's topics that Touchline cannot tell by their type: which
 * topic is the robot's pose, its log, and which field holds its battery or the game state. A
 * properties file ({@code ros2-mapping.properties} in the configuration directory, see
 * docs/user-guide.md#ros-2-robots):
 * <pre>
 * pose = /localization/pose            (x, y, theta; or a pose; or a position)
 * log = /behavior/say                  (msg, data or text)
 * battery./power = battery_level       (topic = numeric field path; 0…1 or 0…100)
 * gameState./referee = state           (topic = field path; a name or the GameController's number)
 * </pre>
 * Several topics are separated by commas. A line it does not understand is listed in
 * {@link #problems()}, and the rest still applies.
 */
public final class RosMapping {

    public static final RosMapping NONE = new RosMapping(Set.of(), Set.of(), Map.of(), Map.of(), List.of());

    private final Set<String> poseTopics;
    private final Set<String> logTopics;
    private final Map<String, String> batteryPaths;
    private final Map<String, String> gameStatePaths;
    private final List<String> problems;

    private RosMapping(Set<String> poseTopics, Set<String> logTopics, Map<String, String> batteryPaths,
                       Map<String, String> gameStatePaths, List<String> problems) {
        this.poseTopics = poseTopics;
        this.logTopics = logTopics;
        this.batteryPaths = batteryPaths;
        this.gameStatePaths = gameStatePaths;
        this.problems = problems;
    }

    /** The mapping in {@code text} (properties syntax). */
    public static RosMapping parse(Reader text) throws IOException {
        Properties p = new Properties();
        p.load(text);
        Set<String> pose = new TreeSet<>();
        Set<String> log = new TreeSet<>();
        Map<String, String> battery = new TreeMap<>();
        Map<String, String> game = new TreeMap<>();
        List<String> problems = new ArrayList<>();
        for (String key : new TreeSet<>(p.stringPropertyNames())) {
            String value = p.getProperty(key).trim();
            if (key.equals("pose")) {
                pose.addAll(topics(value));
            } else if (key.equals("log")) {
                log.addAll(topics(value));
            } else if (key.startsWith("battery./") && !value.isEmpty()) {
                battery.put(key.substring("battery.".length()), value);
            } else if (key.startsWith("gameState./") && !value.isEmpty()) {
                game.put(key.substring("gameState.".length()), value);
            } else {
                problems.add(key + " = " + value + ": not pose, log, battery./TOPIC or gameState./TOPIC");
            }
        }
        return new RosMapping(pose, log, battery, game, List.copyOf(problems));
    }

    /** The mapping in {@code file}; none when the file does not exist. IOException when it cannot be read. */
    public static RosMapping read(Path file) throws IOException {
        if (!Files.exists(file)) {
            return NONE;
        }
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return parse(r);
        }
    }

    private static List<String> topics(String value) {
        List<String> out = new ArrayList<>();
        for (String t : value.split(",")) {
            if (!t.isBlank()) {
                out.add(t.trim());
            }
        }
        return out;
    }

    boolean poseTopic(String topic) {
        return poseTopics.contains(topic);
    }

    boolean logTopic(String topic) {
        return logTopics.contains(topic);
    }

    Optional<String> batteryPath(String topic) {
        return Optional.ofNullable(batteryPaths.get(topic));
    }

    Optional<String> gameStatePath(String topic) {
        return Optional.ofNullable(gameStatePaths.get(topic));
    }

    /** Lines of the file that mean nothing here, in words. */
    public List<String> problems() {
        return problems;
    }
}
