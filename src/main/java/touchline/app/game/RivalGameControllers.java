package touchline.app.game;

import touchline.protocol.gamecontroller.GameControlData;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.TreeMap;

/**
 * Other GameControllers heard on the game-state port. Two GameControllers on one field confuse
 * every robot, so while any was heard in the last {@link #ACTIVE_MS} ms {@link #warning} is a
 * loud, non-empty text. Kept for the last {@link RecentSources#CAPACITY} sources heard. Thread-safe.
 */
public final class RivalGameControllers {

    public static final long ACTIVE_MS = 3000;

    /**
     * What was last heard from one rival.
     *
     * @param atMs   when
     * @param kind   format kind (e.g. {@code gc.hl12}) or {@code gc.unknown}
     * @param state  decoded game state, or -1 when the packet could not be decoded
     * @param teams  the team numbers it announced, e.g. "13 vs 7" ("" when undecoded)
     * @param count  packets heard from it
     */
    public record Rival(long atMs, String kind, int state, String teams, long count) {
    }

    private final RecentSources<Rival> rivals = new RecentSources<>();

    public synchronized void heard(InetSocketAddress from, String kind, GameControlData data, long nowMs) {
        String key = from.getAddress().getHostAddress() + ":" + from.getPort();
        int state = data == null ? -1 : data.state();
        String teams = data == null ? ""
                : data.teams().get(0).teamNumber() + " vs " + data.teams().get(1).teamNumber();
        Rival before = rivals.get(key);
        rivals.put(key, new Rival(nowMs, kind, state, teams, before == null ? 1 : before.count + 1));
    }

    /** Rivals heard within {@link #ACTIVE_MS}: the {@link RecentSources#CAPACITY} heard last at most. */
    public synchronized Map<String, Rival> active(long nowMs) {
        Map<String, Rival> out = new TreeMap<>();
        for (Map.Entry<String, Rival> e : rivals.entries()) {
            if (nowMs - e.getValue().atMs <= ACTIVE_MS) {
                out.put(e.getKey(), e.getValue());
            }
        }
        return out;
    }

    /** Rival sources forgotten because more than {@link RecentSources#CAPACITY} sent. */
    public synchronized long forgotten() {
        return rivals.forgotten();
    }

    /** "" when no other GameController is active, else the warning to show. */
    public String warning(long nowMs) {
        Map<String, Rival> active = active(nowMs);
        if (active.isEmpty()) {
            return "";
        }
        StringBuilder b = new StringBuilder("WARNING: ANOTHER GAMECONTROLLER IS SENDING on this network: ");
        active.forEach((k, r) -> b.append(k).append(" (").append(r.kind)
                .append(r.state >= 0 ? " " + GameControlData.stateName(r.state) + " " + r.teams : "")
                .append(") "));
        return b.append("- robots will follow both; stop one of them").toString();
    }
}
