package touchline.security;

import java.util.HashSet;
import java.util.Set;

/**
 * The console's memory of each robot's counter (robot → console): a robot's counter is its
 * boot id (random per start) in the high word and a sequence in the low word. A higher
 * counter of the same boot is accepted; a new boot id is a restart (accepted and noted: "robot
 * 3 restarted: counter reset, accepted"); anything else (the same or an older counter, or a
 * boot id seen before in this session) is a replay. Pure; bounded by the 256 robot ids. Not
 * thread-safe: its owner ({@link InboundVerifier}) checks one datagram at a time. Nothing is
 * allocated per datagram of a known robot (it runs for every tagged datagram the console takes).
 */
public final class ReplayGuard {

    /** The verdict on one counter; {@code restarted} when it began a new boot. */
    public record Verdict(boolean accepted, boolean restarted) { }

    private static final Verdict ACCEPTED = new Verdict(true, false);
    private static final Verdict RESTARTED = new Verdict(true, true);
    private static final Verdict REPLAYED = new Verdict(false, false);

    private static final int MAX_BOOTS_REMEMBERED = 64;

    private static final class Seen {
        long highest;
        final Set<Integer> boots = new HashSet<>();
    }

    private final Seen[] robots = new Seen[256];

    public Verdict check(int robotId, long counter) {
        Seen s = robots[robotId & 0xFF];
        int boot = (int) (counter >>> 32);
        if (s == null) {
            s = new Seen();
            robots[robotId & 0xFF] = s;
            s.highest = counter;
            s.boots.add(boot);
            return ACCEPTED;
        }
        int currentBoot = (int) (s.highest >>> 32);
        if (boot == currentBoot) {
            if (Long.compareUnsigned(counter, s.highest) <= 0) {
                return REPLAYED;
            }
            s.highest = counter;
            return ACCEPTED;
        }
        if (s.boots.contains(boot)) {
            return REPLAYED; // a capture of an earlier boot played back
        }
        if (s.boots.size() >= MAX_BOOTS_REMEMBERED) {
            s.boots.clear();
        }
        s.boots.add(boot);
        s.highest = counter;
        return RESTARTED;
    }
}
