package touchline.model;

import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.ros2.RosMessage;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * What a ROS 2 robot's messages say of the robot, by message type with no configuration (the
 * types every ROS 2 robot publishes), and by the user's {@link RosMapping} for the rest: its
 * pose on the field, its battery, the game state it believes, its log lines. Pure: one decoded
 * message in, a value (or none) out.
 */
public final class RosReadings {

    /** A robot's pose on the field: metres, radians. */
    public record Pose(double x, double y, double theta) { }

    /** A pose and the frame it is given in: {@code header.frame_id}, or "" for a message without one (Pose2D, Pose, a mapped topic). */
    public record FramedPose(String frame, Transform2D pose) { }

    /** One log line: the level's word (DEBUG … FATAL), the node, the text. */
    public record LogLine(String level, String node, String text) { }

    private final RosMapping mapping;

    public RosReadings(RosMapping mapping) {
        this.mapping = mapping;
    }

    /** Readings by message type only. */
    public RosReadings() {
        this(RosMapping.NONE);
    }

    /** The pose a message on {@code topic} gives, if it is one of the pose types (or mapped as a pose). */
    public Optional<Pose> pose(String topic, RosMessage m) {
        String prefix = switch (m.typeName()) {
            case "geometry_msgs/msg/PoseStamped", "geometry_msgs/msg/PoseWithCovariance" -> "pose.";
            case "geometry_msgs/msg/PoseWithCovarianceStamped", "nav_msgs/msg/Odometry" -> "pose.pose.";
            case "geometry_msgs/msg/Pose" -> "";
            case "geometry_msgs/msg/Pose2D" -> null;
            case "geometry_msgs/msg/TransformStamped" -> "transform.";
            case "tf2_msgs/msg/TFMessage" -> baseTransform(m);
            default -> mapping.poseTopic(topic) ? mappedPose(m) : "-";
        };
        if (prefix == null) {
            return finite(m.number("x"), m.number("y"), m.number("theta"));
        }
        if (prefix.equals("-")) {
            return Optional.empty();
        }
        boolean transform = prefix.endsWith("transform.");
        String position = prefix + (transform ? "translation." : "position.");
        String rotation = prefix + (transform ? "rotation." : "orientation.");
        double qx = m.number(rotation + "x");
        double qy = m.number(rotation + "y");
        double qz = m.number(rotation + "z");
        double qw = m.number(rotation + "w");
        double yaw = Math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz));
        return finite(m.number(position + "x"), m.number(position + "y"), yaw);
    }

    /**
     * The pose a message gives ({@link #pose}) with the frame it is in: a stamped pose's or an
     * odometry's {@code header.frame_id}, a transform's parent frame (the robot's base in it).
     */
    public Optional<FramedPose> framedPose(String topic, RosMessage m) {
        Optional<Pose> pose = pose(topic, m);
        if (pose.isEmpty()) {
            return Optional.empty();
        }
        String header = switch (m.typeName()) {
            case "geometry_msgs/msg/PoseStamped", "geometry_msgs/msg/PoseWithCovarianceStamped", "nav_msgs/msg/Odometry",
                 "geometry_msgs/msg/TransformStamped" -> "header.frame_id";
            case "tf2_msgs/msg/TFMessage" -> baseTransform(m).replace("transform.", "header.frame_id");
            default -> null;
        };
        Pose p = pose.get();
        return Optional.of(new FramedPose(header == null ? "" : frameId(m.at(header)), new Transform2D(p.x(), p.y(), p.theta())));
    }

    /** The TF links of a {@code tf2_msgs/msg/TFMessage} ({@code /tf}, {@code /tf_static}) or a lone TransformStamped. */
    public List<FrameTree.Link> links(RosMessage m) {
        if (m.typeName().equals("geometry_msgs/msg/TransformStamped")) {
            return link(m).map(List::of).orElse(List.of());
        }
        if (!m.typeName().equals("tf2_msgs/msg/TFMessage") || !(m.get("transforms") instanceof RosMessage[] all)) {
            return List.of();
        }
        List<FrameTree.Link> out = new ArrayList<>(all.length);
        for (RosMessage t : all) {
            link(t).ifPresent(out::add);
        }
        return out;
    }

    private static Optional<FrameTree.Link> link(RosMessage t) {
        Transform2D tf = Transform2D.of(t.number("transform.translation.x"), t.number("transform.translation.y"),
                t.number("transform.rotation.x"), t.number("transform.rotation.y"), t.number("transform.rotation.z"),
                t.number("transform.rotation.w"));
        String parent = frameId(t.at("header.frame_id"));
        String child = frameId(t.get("child_frame_id"));
        return tf.isFinite() && !parent.isEmpty() && !child.isEmpty()
                ? Optional.of(new FrameTree.Link(parent, child, tf)) : Optional.empty();
    }

    /** A frame id as tf2 writes it: without ROS 1's leading slash. */
    static String frameId(Object id) {
        return id instanceof String s ? s.strip().replaceFirst("^/+", "") : "";
    }

    /** A mapped pose topic's shape: x, y, theta (null); a pose ({@code pose.}); or a bare position (""). */
    private static String mappedPose(RosMessage m) {
        if (!Double.isNaN(m.number("theta"))) {
            return null;
        }
        return Double.isNaN(m.number("pose.position.x")) ? "" : "pose.";
    }

    /** The transform of a TF message that places the robot's base: {@code transforms[i].}, or "-" for none. */
    private static String baseTransform(RosMessage m) {
        Object list = m.get("transforms");
        if (list instanceof RosMessage[] transforms) {
            for (int i = 0; i < transforms.length; i++) {
                Object child = transforms[i].get("child_frame_id");
                if (child instanceof String c && c.toLowerCase(Locale.ROOT).contains("base")) {
                    return "transforms[" + i + "].transform.";
                }
            }
        }
        return "-";
    }

    private static Optional<Pose> finite(double x, double y, double theta) {
        return Double.isFinite(x) && Double.isFinite(y)
                ? Optional.of(new Pose(x, y, Double.isFinite(theta) ? theta : 0)) : Optional.empty();
    }

    /**
     * The battery in percent: {@code sensor_msgs/msg/BatteryState}'s percentage, a field the mapping
     * names, a DiagnosticArray's value whose key says battery ({@link RosDiagnostics}), or a numeric
     * field whose path says battery and percent ({@code battery.percentage}, {@code battery_percent});
     * fractions (≤ 1) are taken as 0…1.
     */
    public Optional<Integer> batteryPercent(String topic, RosMessage m) {
        String path = mapping.batteryPath(topic).orElse(null);
        if (path == null && m.typeName().equals("sensor_msgs/msg/BatteryState")) {
            path = "percentage";
        }
        if (path == null && m.typeName().equals("diagnostic_msgs/msg/DiagnosticArray")) {
            var level = new RosDiagnostics().batteryPercent(m); // a "Battery" key/value
            return level.isPresent() ? Optional.of((int) Math.round(level.getAsDouble())) : Optional.empty();
        }
        if (path == null && m.namesContain("battery")) { // every message of every robot passes here: no paths built for most
            for (String p : m.numericPaths()) {
                String l = p.toLowerCase(Locale.ROOT);
                if (l.contains("battery") && l.contains("percent")) {
                    path = p;
                    break;
                }
            }
        }
        double v = path == null ? Double.NaN : m.number(path);
        if (!Double.isFinite(v) || v < 0) {
            return Optional.empty();
        }
        return Optional.of((int) Math.round(Math.min(100, v <= 1 ? v * 100 : v)));
    }

    /**
     * The game state the robot believes, as the GameController names it (INITIAL … FINISHED): the
     * field the mapping names, or a field named like the HSL GameController's ({@code game_state},
     * {@code gameState}) holding a name or the GameController's number.
     */
    public Optional<String> gameState(String topic, RosMessage m) {
        Object v = mapping.gameStatePath(topic).map(m::at).orElse(null);
        if (v == null) {
            v = m.get("game_state");
        }
        if (v == null) {
            v = m.get("gameState");
        }
        if (v instanceof Number n) {
            int code = n.intValue();
            return code >= 0 && code <= GameControlData.STATE_FINISHED
                    ? Optional.of(GameControlData.stateName(code)) : Optional.empty();
        }
        if (v instanceof String s) {
            String name = s.trim().toUpperCase(Locale.ROOT).replaceFirst("^(STATE_|GAMESTATE_)", "");
            int code = GameControlData.stateCode(name);
            return code >= 0 && code <= GameControlData.STATE_FINISHED ? Optional.of(name) : Optional.empty();
        }
        return Optional.empty();
    }

    /** A log line: {@code rcl_interfaces/msg/Log} (/rosout), or a topic the mapping names as a log. */
    public Optional<LogLine> log(String topic, RosMessage m) {
        if (m.typeName().equals("rcl_interfaces/msg/Log") || m.typeName().equals("rosgraph_msgs/Log")) {
            double level = m.number("level");
            return Optional.of(new LogLine(level(level), String.valueOf(m.get("name")), String.valueOf(m.get("msg"))));
        }
        if (mapping.logTopic(topic)) {
            Object text = m.get("msg") != null ? m.get("msg") : m.get("data") != null ? m.get("data") : m.get("text");
            return Optional.of(new LogLine("INFO", topic, text == null ? m.line(400) : String.valueOf(text)));
        }
        return Optional.empty();
    }

    /** ROS 2's levels (10 … 50) in words. */
    static String level(double level) {
        if (level >= 50) {
            return "FATAL";
        }
        if (level >= 40) {
            return "ERROR";
        }
        if (level >= 30) {
            return "WARN";
        }
        if (level >= 20) {
            return "INFO";
        }
        return "DEBUG";
    }
}
