package touchline.model;

import touchline.proto.Fumanoid;
import touchline.protocol.ros2.RosMessage;

import java.util.Locale;
import java.util.Optional;

/**
 * A ROS 2 robot's joint states and diagnostics as tables: {@code sensor_msgs/msg/JointState} →
 * one row per joint (name, position, velocity, effort; a missing value empty);
 * {@code diagnostic_msgs/msg/DiagnosticArray} → one row per status (name, level, message,
 * hardware id, its key/values). Pure.
 */
public final class RosTables {

    static final String[] LEVELS = {"OK", "WARN", "ERROR", "STALE"};

    /** Whether messages of {@code typeName} are tables here. */
    public static boolean isTable(String typeName) {
        return typeName.equals("sensor_msgs/msg/JointState") || typeName.equals("diagnostic_msgs/msg/DiagnosticArray");
    }

    /** The table {@code m} on {@code topic} is, if it is one of the two types. */
    public Optional<Fumanoid.DebugTable> table(String topic, RosMessage m) {
        return switch (m.typeName()) {
            case "sensor_msgs/msg/JointState" -> Optional.of(joints(topic, m));
            case "diagnostic_msgs/msg/DiagnosticArray" -> Optional.of(diagnostics(topic, m));
            default -> Optional.empty();
        };
    }

    private static Fumanoid.DebugTable joints(String topic, RosMessage m) {
        Fumanoid.DebugTable.Builder t = Fumanoid.DebugTable.newBuilder().setOption(topic)
                .addHeader("joint").addHeader("position").addHeader("velocity").addHeader("effort");
        Object names = m.get("name");
        int count = names instanceof String[] n ? n.length : names instanceof Object[] o ? o.length : 0;
        for (int i = 0; i < count; i++) {
            t.addRows(Fumanoid.TableRow.newBuilder().addCells(String.valueOf(m.at("name[" + i + "]"))).addCells(cell(m, "position", i))
                    .addCells(cell(m, "velocity", i)).addCells(cell(m, "effort", i)));
        }
        return t.build();
    }

    private static String cell(RosMessage m, String field, int i) {
        double v = m.number(field + "[" + i + "]");
        return Double.isNaN(v) ? "" : String.format(Locale.ROOT, "%.3f", v);
    }

    private static Fumanoid.DebugTable diagnostics(String topic, RosMessage m) {
        Fumanoid.DebugTable.Builder t = Fumanoid.DebugTable.newBuilder().setOption(topic)
                .addHeader("name").addHeader("level").addHeader("message").addHeader("hardware").addHeader("values");
        for (RosMessage s : statuses(m)) {
            StringBuilder values = new StringBuilder();
            if (s.get("values") instanceof RosMessage[] kv) {
                for (RosMessage p : kv) {
                    values.append(values.length() == 0 ? "" : ", ").append(p.get("key")).append('=').append(p.get("value"));
                }
            }
            t.addRows(Fumanoid.TableRow.newBuilder().addCells(String.valueOf(s.get("name")))
                    .addCells(level(s.number("level"))).addCells(String.valueOf(s.get("message")))
                    .addCells(String.valueOf(s.get("hardware_id"))).addCells(values.toString()));
        }
        return t.build();
    }

    /** A DiagnosticArray's statuses (none for another message). */
    static RosMessage[] statuses(RosMessage m) {
        return m.get("status") instanceof RosMessage[] s ? s : new RosMessage[0];
    }

    private static String level(double level) {
        int l = (int) level;
        return l >= 0 && l < LEVELS.length && l == level ? LEVELS[l] : String.valueOf(level);
    }
}
