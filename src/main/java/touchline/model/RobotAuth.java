package touchline.model;

import touchline.proto.Fumanoid;
import touchline.security.Authenticity;

/**
 * A robot's authenticity as the console sees it (docs/security.md): how its data arrived
 * (verified, unverified), how many datagrams claiming to be it were forged and where the last
 * came from, and what the robot itself refused from consoles (its Status' counters).
 *
 * @param state         the last accepted datagram's authenticity; FORGED when only forgeries claimed this id
 * @param forged        datagrams claiming this robot that were dropped
 * @param lastForgery   "10.0.0.9:4000: forged: bad tag", or "" when none
 * @param atRobot       the robot's own verifier counters, or null when it sends none (lab mode)
 */
public record RobotAuth(Authenticity state, long verified, long unverified, long forged, String lastForgery,
                        Fumanoid.AuthCounters atRobot) {

    public static final RobotAuth NONE = new RobotAuth(Authenticity.NOT_CHECKED, 0, 0, 0, "", null);

    /** What the robot refused from consoles, e.g. "3 bad tag, 1 replayed", or "" when nothing. */
    public String rejectedAtRobot() {
        if (atRobot == null) {
            return "";
        }
        StringBuilder b = new StringBuilder();
        part(b, atRobot.getNoTag(), "no tag");
        part(b, atRobot.getTruncated(), "truncated");
        part(b, atRobot.getWrongKey(), "wrong key");
        part(b, atRobot.getBadTag(), "bad tag");
        part(b, atRobot.getReplayed(), "replayed");
        return b.toString();
    }

    private static void part(StringBuilder b, int n, String what) {
        if (n > 0) {
            b.append(b.length() == 0 ? "" : ", ").append(n).append(' ').append(what);
        }
    }

    /** One cell of the robot table: "verified", "unverified", "FORGED ×5", with what the robot rejected. */
    public String describe() {
        StringBuilder b = new StringBuilder(state == Authenticity.NOT_CHECKED ? "—" : state.word());
        if (forged > 0) {
            b.append(state == Authenticity.FORGED ? " ×" : "; forged ×").append(forged);
        }
        String rejected = rejectedAtRobot();
        if (!rejected.isEmpty()) {
            b.append("; robot rejected: ").append(rejected);
        }
        return b.toString();
    }
}
