package touchline.cli;

import touchline.model.MatchDebugRule;
import touchline.model.RobotSnapshot;
import touchline.model.SourceSnapshot;

import java.io.PrintStream;
import java.util.List;

/**
 * The robot view as text: one row per robot (with the debug rule's reading while it is in play,
 * as the Robots table's "Debug in play" column), then every source that sent bad datagrams.
 */
final class RobotTable {

    private final java.util.function.IntFunction<MatchDebugRule.Reading> inPlay;

    /** @param inPlay the debug rule's reading of a robot ({@code MatchDebugRule::reading}) */
    RobotTable(java.util.function.IntFunction<MatchDebugRule.Reading> inPlay) {
        this.inPlay = inPlay;
    }

    void print(PrintStream out, List<RobotSnapshot> robots, List<SourceSnapshot> sources, List<String> notes) {
        out.printf("%-4s %-12s %-4s %-4s %-10s %-12s %-9s %-7s %6s %8s %8s %5s %s%n",
                "ID", "NAME", "TEAM", "BAT", "ROLE", "STATE", "GAME", "ONLINE", "PKTS", "PKT/S", "B/S", "BAD", "AUTH");
        for (RobotSnapshot r : robots) {
            out.printf("%-4d %-12s %-4s %-4s %-10s %-12s %-9s %-7s %6d %8.1f %8.0f %5d %s%n", r.id(), r.label(),
                    r.teamId() < 0 ? "?" : r.teamId(), r.batteryPercent() < 0 ? "?" : r.batteryPercent() + "%",
                    r.role(), r.state(), r.gameState(), r.online() ? "online" : "OFFLINE", r.packets(),
                    r.packetsPerSecond(), r.bytesPerSecond(), r.malformed(), r.auth().describe());
            MatchDebugRule.Reading m = r.replayed() ? null : inPlay.apply(r.id());
            if (m != null && m.inPlay()) {
                out.printf("  robot %d in play: %s%s%n", r.id(), m.describe(),
                        m.warnings().isEmpty() ? "" : " — BREAKS THE DEBUG RULE");
            }
            if (r.gcOtherSource() > 0) {
                out.printf("  robot %d: %d GameController packet(s) from another source than the one it follows, "
                        + "not believed%n", r.id(), r.gcOtherSource());
            }
            if (r.auth().forged() > 0) {
                out.printf("  robot %d: %d forged datagram(s) dropped; last from %s%n", r.id(), r.auth().forged(),
                        r.auth().lastForgery());
            }
        }
        for (SourceSnapshot s : sources) {
            if (s.malformed() > 0) {
                out.printf("  source %s: %d malformed of %d; last: %s%n", s.label(), s.malformed(), s.packets(),
                        s.lastError());
            }
        }
        for (String note : notes) {
            out.println("  note: " + note);
        }
    }
}
