package touchline.app.game;

import java.util.List;

/**
 * The robots as the field's GameController sees them, when this console is its monitor
 * ({@code --gc-monitor}): how many it has heard of, and one line each (team/player, host,
 * penalty, age) for the robots view and {@code listen}'s table.
 */
public record MonitorReport(int robots, List<String> lines) {

    public MonitorReport {
        lines = List.copyOf(lines);
    }
}
