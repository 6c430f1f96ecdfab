package touchline.security;

/**
 * The console's check of each robot's counter (robot → console): the robot's boot number in
 * the high word (counted up by the robot, kept in its flash) and a sequence in the low word. A
 * counter of the boot believed ({@link RobotBoots}) must be higher than the last one taken; a
 * higher boot is the robot's restart (accepted, noted); a lower boot is a capture of an earlier
 * boot and is refused, so no old datagram can displace the robot's current boot or make the
 * console refuse its current datagrams. Bounded by the 256 robot ids; a new boot believed goes to
 * {@link RobotBoots} (kept in the key directory), everything else is memory. Not thread-safe: its
 * owner ({@link InboundVerifier}) checks one datagram at a time. Nothing is allocated per
 * datagram (it runs for every tagged datagram the console takes).
 */
public final class ReplayGuard {

    /** The verdict on one counter. */
    public enum Verdict {
        ACCEPTED, RESTARTED, REPLAYED, EARLIER_BOOT;

        public boolean accepted() {
            return this == ACCEPTED || this == RESTARTED;
        }

        public boolean restarted() {
            return this == RESTARTED;
        }
    }

    private final RobotBoots boots;
    private final long[] highest = new long[256];
    private final boolean[] seen = new boolean[256];

    public ReplayGuard(RobotBoots boots) {
        this.boots = boots;
    }

    /** A guard whose boots live in memory only (tests). */
    public ReplayGuard() {
        this(new RobotBoots(RobotBoots.inMemory()));
    }

    public Verdict check(int robotId, long counter) {
        int id = robotId & 0xFF;
        int boot = (int) (counter >>> 32);
        java.util.OptionalInt believed = boots.believed(id);
        int order = believed.isEmpty() ? 1 : Integer.compareUnsigned(boot, believed.getAsInt());
        if (order < 0) {
            return Verdict.EARLIER_BOOT;
        }
        if (order > 0) {
            boots.believe(id, boot);
            take(id, counter);
            return believed.isEmpty() ? Verdict.ACCEPTED : Verdict.RESTARTED;
        }
        if (seen[id] && (int) (highest[id] >>> 32) == boot && Long.compareUnsigned(counter, highest[id]) <= 0) {
            return Verdict.REPLAYED;
        }
        take(id, counter);
        return Verdict.ACCEPTED;
    }

    private void take(int id, long counter) {
        highest[id] = counter;
        seen[id] = true;
    }
}
