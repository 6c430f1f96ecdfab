package touchline.cli;

import touchline.transport.gamecontroller.GcMonitor;
import touchline.transport.gamecontroller.RobotLiveness;

import java.io.PrintStream;
import java.util.Map;

/** Each robot as the field's GameController sees it (with {@code --gc-monitor}), as text lines. */
final class MonitorTable {

    void print(PrintStream out, GcMonitor monitor, long nowMs) {
        if (monitor == null) {
            return;
        }
        Map<RobotLiveness.RobotKey, GcMonitor.Seen> robots = monitor.robots();
        out.println("GameController sees " + robots.size() + " robot(s):");
        robots.forEach((key, seen) -> {
            var p = seen.packet();
            out.printf("  %-6s %-15s %-7s %s pose (%.0f, %.0f, %.2f) ball %s%n", key, seen.robotHost(),
                    monitor.liveness().status(key.team(), key.player(), nowMs), p.fallen() == 1 ? "FALLEN " : "upright",
                    p.poseX(), p.poseY(), p.poseTheta(),
                    p.ballAge() < 0 ? "never seen" : String.format("(%.0f, %.0f) %.1f s ago", p.ballX(), p.ballY(),
                            p.ballAge()));
        });
        monitor.badPackets().bySource().forEach((src, t) ->
                out.println("  bad forwarded packets from " + src + ": " + t.count() + " (last: " + t.lastReason() + ")"));
    }
}
