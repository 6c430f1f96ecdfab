package touchline.app.game;

import touchline.protocol.gamecontroller.GameControlData;

import java.net.InetSocketAddress;
import java.util.Map;
import java.util.TreeMap;

/**
 * Other GameControllers heard on the game-state port: the one tracker of them. While this
 * console referees, every other GameController is a rival; while it only listens, those that
 * are not the pinned one are intruders ({@link GameControllerSources}, which keeps its table
 * here). Two GameControllers on one field confuse every robot, so while any was heard in the
 * last {@link #ACTIVE_MS} ms {@link #warning} is a loud, non-empty text. Kept for the last
 * {@link RecentSources#CAPACITY} sources heard. Thread-safe.
 */
public final class RivalGameControllers {

    /**
     * How long a source counts as sending: {@link MatchMode#STALE_MS}, as long as its claim of
     * play keeps match mode silent (ten missed 500 ms packets), so the warning never ends while
     * what it warns of still acts.
     */
    public static final long ACTIVE_MS = MatchMode.STALE_MS;

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

    public void heard(InetSocketAddress from, String kind, GameControlData data, long nowMs) {
        heard(from.getAddress().getHostAddress() + ":" + from.getPort(), kind, data, nowMs);
    }

    /** @param key the source, "address:port" */
    public synchronized void heard(String key, String kind, GameControlData data, long nowMs) {
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

    /** Every source heard, the {@link RecentSources#CAPACITY} heard last at most. */
    public synchronized Map<String, Rival> all() {
        Map<String, Rival> out = new TreeMap<>();
        for (Map.Entry<String, Rival> e : rivals.entries()) {
            out.put(e.getKey(), e.getValue());
        }
        return out;
    }

    /** Whether {@code key} ("address:port") was heard within {@link #ACTIVE_MS}. */
    public synchronized boolean isActive(String key, long nowMs) {
        Rival r = rivals.get(key);
        return r != null && nowMs - r.atMs <= ACTIVE_MS;
    }

    /** The table's capacity. */
    public int capacity() {
        return rivals.capacity();
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
