package touchline.protocol.ros2;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * The real ROS 2 {@code .msg} files under {@code src/test/resources/ros2/msg} (copied from the
 * ROS 2 repositories; see the README there) joined into the {@code ros2msg} form rosbag2 and
 * {@code foxglove_bridge} write: the type's text, then each dependency (depth first) after a
 * line of 80 {@code =} and {@code MSG: pkg/Type}. Kept independent of the parser under test:
 * it only finds the type names a line starts with.
 */
public final class Ros2Sources {

    private static final Set<String> PRIMITIVES = Set.of("bool", "byte", "char", "int8", "uint8", "int16", "uint16",
            "int32", "uint32", "int64", "uint64", "float32", "float64", "string", "wstring");

    private Ros2Sources() {
    }

    /** The .msg text of {@code pkg/msg/Type} as the ROS 2 sources have it. */
    public static String msg(String fullName) {
        String[] p = fullName.split("/");
        String path = "/ros2/msg/" + p[0] + "/msg/" + p[p.length - 1] + ".msg";
        try (InputStream in = Ros2Sources.class.getResourceAsStream(path)) {
            if (in == null) {
                throw new IllegalArgumentException("no test resource " + path);
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** {@code fullName}'s definition with its dependencies, as a bag's ros2msg schema carries it. */
    public static String definition(String fullName) {
        Set<String> deps = new LinkedHashSet<>();
        collect(fullName, deps);
        deps.remove(fullName);
        StringBuilder b = new StringBuilder(msg(fullName));
        for (String d : deps) {
            String[] p = d.split("/");
            b.append("\n").append("=".repeat(80)).append("\nMSG: ").append(p[0]).append('/').append(p[2]).append('\n')
                    .append(msg(d));
        }
        return b.toString();
    }

    private static void collect(String fullName, Set<String> out) {
        if (!out.add(fullName)) {
            return;
        }
        String pkg = fullName.substring(0, fullName.indexOf('/'));
        for (String line : msg(fullName).split("\n")) {
            String s = line.strip();
            if (s.isEmpty() || s.startsWith("#")) {
                continue;
            }
            String type = s.split("\\s+")[0].replaceAll("\\[.*", "").replaceAll("<=.*", "");
            if (PRIMITIVES.contains(type) || s.split("\\s+").length > 1 && s.split("\\s+")[1].contains("=")) {
                continue;
            }
            String[] parts = type.split("/");
            String dep = parts.length == 1 ? (type.equals("Header") ? "std_msgs/msg/Header" : pkg + "/msg/" + type)
                    : parts[0] + "/msg/" + parts[parts.length - 1];
            collect(dep, out);
        }
    }
}
