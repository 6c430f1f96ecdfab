package touchline.cli;

import touchline.transport.gamecontroller.GcMonitor;

import java.io.PrintStream;

/** Each robot as the field's GameController sees it (with {@code --gc-monitor}), as text lines. */
final class MonitorTable {

    void print(PrintStream out, GcMonitor monitor, long nowMs) {
        if (monitor == null) {
            return;
        }
        out.println("GameController sees " + monitor.robots().size() + " robot(s):");
        monitor.describe(nowMs).forEach(line -> out.println("  " + line));
    }
}
