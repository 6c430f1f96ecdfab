package touchline.model;

import org.junit.jupiter.api.Test;
import touchline.protocol.ros2.RosMessage;

import static org.junit.jupiter.api.Assertions.*;

/** Battery and temperature from a ROS 2 robot's diagnostics and messages, where the names say so. */
class RosDiagnosticsTest {

    private static RosMessage msg(String type, String[] names, Object... values) {
        return new RosMessage(type, null, names, values);
    }

    private static RosMessage kv(String key, String value) {
        return msg("diagnostic_msgs/msg/KeyValue", new String[] {"key", "value"}, key, value);
    }

    private static RosMessage diagnostics(String name, RosMessage... values) {
        RosMessage status = msg("diagnostic_msgs/msg/DiagnosticStatus", new String[] {"level", "name", "values"},
                0, name, values);
        return msg("diagnostic_msgs/msg/DiagnosticArray", new String[] {"status"}, (Object) new RosMessage[] {status});
    }

    private final RosDiagnostics diagnostics = new RosDiagnostics();

    @Test
    void aBatteryKeyOrALevelInABatteryStatusIsTheBattery() {
        assertEquals(72.5, diagnostics.batteryPercent(diagnostics("power", kv("Voltage", "25.1"), kv("Battery", "72.5 %")))
                .getAsDouble(), 1e-9, "the voltage is no level");
        assertEquals(40, diagnostics.batteryPercent(diagnostics("booster: Battery", kv("Percentage", "0.4"))).getAsDouble(), 1e-9);
        assertTrue(diagnostics.batteryPercent(diagnostics("motors", kv("Percentage", "40"))).isEmpty());
        assertTrue(diagnostics.batteryPercent(diagnostics("battery", kv("Battery voltage", "24"), kv("Battery", "n/a")))
                .isEmpty());
        assertEquals(73, new RosReadings().batteryPercent("/diagnostics",
                diagnostics("power", kv("Battery", "72.5"))).orElseThrow(), "the Robots table's battery");
    }

    @Test
    void theHottestTemperatureFromKeysOrFieldNames() {
        assertEquals(55.0, diagnostics.temperature(diagnostics("motors", kv("Temperature", "41.5"), kv("knee temp", "55 °C"),
                kv("Load", "90"))).getAsDouble(), 1e-9);
        assertEquals(38.25, diagnostics.temperature(msg("robot_state", new String[] {"battery", "cpu_temp"}, 0.9, 38.25))
                .getAsDouble(), 1e-9);
        assertEquals(21.0, diagnostics.temperature(msg("sensor_msgs/msg/Temperature", new String[] {"temperature", "variance"},
                21.0, 0.1)).getAsDouble(), 1e-9);
        assertTrue(diagnostics.temperature(msg("x", new String[] {"attempts", "temperature_unit"}, 3L, "C")).isEmpty());
    }
}
