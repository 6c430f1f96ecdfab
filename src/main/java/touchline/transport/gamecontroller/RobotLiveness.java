package touchline.transport.gamecontroller;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * When each robot last sent a valid return packet, and what that makes it: ONLINE (< 2 s),
 * LATE (< 4 s) or OFFLINE — the thresholds of both the Java GameController's RobotWatcher and
 * GameController3. Thread-safe.
 */
public final class RobotLiveness {

    public static final long ONLINE_MS = 2000;
    public static final long LATE_MS = 4000;

    /** A robot's connection as the referee sees it. */
    public enum Status { ONLINE, LATE, OFFLINE }

    /**
     * A robot, by team and player number.
     *
     * @param team   team number
     * @param player player number (1-based)
     */
    public record RobotKey(int team, int player) implements Comparable<RobotKey> {
        @Override
        public int compareTo(RobotKey o) {
            return team != o.team ? Integer.compare(team, o.team) : Integer.compare(player, o.player);
        }

        @Override
        public String toString() {
            return team + "/" + player;
        }
    }

    private final Map<RobotKey, Long> lastHeard = new ConcurrentHashMap<>();

    public void heard(int team, int player, long nowMs) {
        lastHeard.put(new RobotKey(team, player), nowMs);
    }

    public Status status(int team, int player, long nowMs) {
        Long at = lastHeard.get(new RobotKey(team, player));
        if (at == null) {
            return Status.OFFLINE;
        }
        long age = nowMs - at;
        return age < ONLINE_MS ? Status.ONLINE : age < LATE_MS ? Status.LATE : Status.OFFLINE;
    }

    /** Every robot ever heard, with its status now, ordered by team and player. */
    public Map<RobotKey, Status> all(long nowMs) {
        Map<RobotKey, Status> out = new TreeMap<>();
        for (RobotKey k : lastHeard.keySet()) {
            out.put(k, status(k.team(), k.player(), nowMs));
        }
        return out;
    }
}
