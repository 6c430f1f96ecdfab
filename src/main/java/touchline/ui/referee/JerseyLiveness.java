package touchline.ui.referee;

import touchline.model.RobotSnapshot;
import touchline.transport.gamecontroller.RobotLiveness;

import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Whether the robot wearing a jersey is alive, so that the referee box and the Robots view
 * never disagree: a robot the Robots view lists (its keep-alives name team and player) is
 * online or offline exactly as that view says; only a robot the console does not know (one
 * without Touchline's firmware) is judged by the GameController's return packets (online,
 * late, offline, as the official GameController does). Built once per frame.
 */
final class JerseyLiveness {

    private final Map<Long, Boolean> robotsView = new HashMap<>();
    private final Map<RobotLiveness.RobotKey, RobotLiveness.Status> returns;

    /**
     * @param robots  the Robots view's rows (the console's robot registry) this frame
     * @param returns the GameController's return packets, or null
     * @param nowMs   the game's time for the return packets' age
     */
    JerseyLiveness(List<RobotSnapshot> robots, RobotLiveness returns, long nowMs) {
        for (RobotSnapshot r : robots) {
            // a replayed robot is last match's, never a robot on this field
            if (r.teamId() != RobotSnapshot.UNKNOWN && r.origin() == touchline.transport.Origin.LIVE) {
                robotsView.put(key(r.teamId(), r.id()), r.online());
            }
        }
        this.returns = returns == null ? Map.of() : returns.all(nowMs);
    }

    private static long key(int team, int player) {
        return ((long) team << 32) | (player & 0xFFFFFFFFL);
    }

    /** "online", "offline", "late", or "–" when nothing was ever heard of it. */
    String status(int team, int player) {
        Boolean listed = robotsView.get(key(team, player));
        if (listed != null) {
            return listed ? "online" : "offline";
        }
        RobotLiveness.Status heard = returns.get(new RobotLiveness.RobotKey(team, player));
        return heard == null ? "–" : heard.name().toLowerCase(Locale.ROOT);
    }
}
