package touchline.cli;

import touchline.app.game.MonitorReport;

import java.io.PrintStream;

/** Each robot as the field's GameController sees it (with {@code --gc-monitor}), as text lines. */
final class MonitorTable {

    void print(PrintStream out, java.util.Optional<MonitorReport> monitor) {
        if (monitor.isEmpty()) {
            return;
        }
        out.println("GameController sees " + monitor.get().robots() + " robot(s):");
        monitor.get().lines().forEach(line -> out.println("  " + line));
    }
}
