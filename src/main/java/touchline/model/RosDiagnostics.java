package touchline.model;

import touchline.protocol.ros2.RosMessage;

import java.util.Locale;
import java.util.OptionalDouble;

/**
 * What a ROS 2 robot's {@code diagnostic_msgs/msg/DiagnosticArray} and its other messages say
 * of its battery and temperature, where the names say so: a status value whose key says
 * battery ({@code Battery}, {@code battery_percent}; or {@code percentage}, {@code charge},
 * {@code level} in a status whose name says battery), and a key or a numeric field whose name
 * says temperature ({@code Temperature}, {@code temp}, {@code cpu_temp}; the hottest when there
 * are several). Voltages and currents are not a battery level. Pure.
 */
public final class RosDiagnostics {

    /** The battery level a DiagnosticArray reports, 0…100 (a fraction ≤ 1 read as 0…1), if any. */
    public OptionalDouble batteryPercent(RosMessage m) {
        for (RosMessage status : RosTables.statuses(m)) {
            boolean batteryStatus = lower(status.get("name")).contains("battery");
            for (RosMessage kv : values(status)) {
                String key = lower(kv.get("key"));
                if (key.contains("volt") || key.contains("current") || key.contains("temp")) {
                    continue;
                }
                boolean level = key.contains("percent") || key.contains("charge") || key.contains("level");
                double v = number(kv.get("value"));
                if ((key.contains("battery") || batteryStatus && level) && Double.isFinite(v) && v >= 0) {
                    return OptionalDouble.of(Math.min(100, v <= 1 ? v * 100 : v));
                }
            }
        }
        return OptionalDouble.empty();
    }

    /** The hottest temperature {@code m} reports, degrees Celsius as sent, if any. */
    public OptionalDouble temperature(RosMessage m) {
        double[] hottest = {Double.NaN};
        for (RosMessage status : RosTables.statuses(m)) {
            for (RosMessage kv : values(status)) {
                if (saysTemperature(lower(kv.get("key")))) {
                    hottest[0] = hotter(hottest[0], number(kv.get("value")));
                }
            }
        }
        m.forEachNumber((path, value) -> {
            String leaf = path.substring(path.lastIndexOf('.') + 1).toLowerCase(Locale.ROOT);
            if (saysTemperature(leaf)) {
                hottest[0] = hotter(hottest[0], value);
            }
        });
        return Double.isNaN(hottest[0]) ? OptionalDouble.empty() : OptionalDouble.of(hottest[0]);
    }

    private static boolean saysTemperature(String name) {
        return name.contains("temperature") || name.equals("temp") || name.startsWith("temp_") || name.endsWith("_temp")
                || name.contains(" temp");
    }

    private static double hotter(double a, double b) {
        return !Double.isFinite(b) || b < -100 || b > 1000 ? a : Double.isNaN(a) ? b : Math.max(a, b);
    }

    private static RosMessage[] values(RosMessage status) {
        return status.get("values") instanceof RosMessage[] v ? v : new RosMessage[0];
    }

    private static String lower(Object o) {
        return o == null ? "" : o.toString().toLowerCase(Locale.ROOT);
    }

    private static double number(Object value) {
        if (value == null) {
            return Double.NaN;
        }
        String s = value.toString().trim().replaceAll("\\s*(%|°?C|degC|V)$", "");
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }
}
