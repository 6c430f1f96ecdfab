package touchline.app.game;

import touchline.protocol.gamecontroller.GameControlData;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Other GameControllers heard on the game-state port. Two GameControllers on one field confuse
 * every robot, so while any was heard in the last {@link #ACTIVE_MS} ms {@link #warning} is a
 * loud, non-empty text. Thread-safe.
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

    private final Map<String, Rival> rivals = new ConcurrentHashMap<>();

    public void heard(InetSocketAddress from, String kind, GameControlData data, long nowMs) {
        String key = from.getAddress().getHostAddress() + ":" + from.getPort();
        int state = data == null ? -1 : data.state();
        String teams = data == null ? ""
                : data.teams().get(0).teamNumber() + " vs " + data.teams().get(1).teamNumber();
        rivals.merge(key, new Rival(nowMs, kind, state, teams, 1),
                (a, b) -> new Rival(nowMs, kind, state, teams, a.count + 1));
    }

    /** Rivals heard within {@link #ACTIVE_MS}. */
    public Map<String, Rival> active(long nowMs) {
        Map<String, Rival> out = new TreeMap<>();
        rivals.forEach((k, r) -> {
            if (nowMs - r.atMs <= ACTIVE_MS) {
                out.put(k, r);
            }
        });
        return out;
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
