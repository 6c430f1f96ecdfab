package touchline.security;

import java.util.Map;
import java.util.concurrent.atomic.AtomicLongArray;

/**
 * The boot each keyed robot is believed to run (docs/security.md, "Boots"): the highest boot
 * number the console has verified from it, the high word of the robot's own counter. A robot
 * counts its boots up (in flash), so a verified datagram of a higher boot is the robot's restart
 * and one of a lower boot is an old capture: it never displaces the boot believed. The console
 * tags its requests for the believed boot ({@link MessageTag#toRobot}). Remembered across the
 * console's runs in the key directory ({@link Store}), so a console started after a capture does
 * not take it either. Bounded by the 256 robot ids; read from any thread, raised by the verifier.
 */
public final class RobotBoots {

    /** Where the boots live between runs (a file in the key directory; memory in tests). */
    public interface Store {
        /** Robot id → its highest boot (unsigned). */
        Map<Integer, Integer> load();

        /** Keeps {@code boot} for the robot unless a higher one is already kept. */
        void raise(int robotId, int boot);
    }

    private static final long UNKNOWN = -1;

    private final AtomicLongArray believed = new AtomicLongArray(256);
    private final Store store;

    public RobotBoots(Store store) {
        this.store = store;
        for (int i = 0; i < 256; i++) {
            believed.set(i, UNKNOWN);
        }
        store.load().forEach((robot, boot) -> believed.set(robot & 0xFF, Integer.toUnsignedLong(boot)));
    }

    /** Boots kept in memory only (tests, and a console without a writable key directory). */
    public static Store inMemory() {
        return new Store() {
            @Override
            public Map<Integer, Integer> load() {
                return Map.of();
            }

            @Override
            public void raise(int robotId, int boot) {
            }
        };
    }

    /** The boot believed for the robot, or empty before any verified datagram of it. */
    public java.util.OptionalInt believed(int robotId) {
        long b = believed.get(robotId & 0xFF);
        return b == UNKNOWN ? java.util.OptionalInt.empty() : java.util.OptionalInt.of((int) b);
    }

    /** A verified datagram of a higher boot (or the first): it is now the robot's boot, kept in the store. */
    void believe(int robotId, int boot) {
        believed.set(robotId & 0xFF, Integer.toUnsignedLong(boot));
        store.raise(robotId & 0xFF, boot);
    }
}
