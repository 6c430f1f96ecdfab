package touchline.security;

import java.util.function.LongSupplier;

/**
 * The console's strictly increasing counter for the tags it sends: max(last + 1, microseconds
 * since the epoch), so a clock that jumps back still moves forward. Runs of the console never
 * go back either: every counter handed out stays below a reservation kept in the key directory
 * ({@link Store}), renewed 10 s ahead whenever the counter reaches it, and a new run starts
 * above the last reservation.
 */
public final class CounterSource {

    /** Where the reservation lives (a file in the key directory; memory in tests). */
    public interface Store {
        long load();

        void save(long reservedUpTo);
    }

    static final long RESERVE_MICROS = 10_000_000;

    private final LongSupplier micros;
    private final Store store;
    private long last;
    private long reserved;

    public CounterSource(LongSupplier micros, Store store) {
        this.micros = micros;
        this.store = store;
        this.last = store.load();
        this.reserved = last;
    }

    public synchronized long next() {
        long c = Math.max(last + 1, micros.getAsLong());
        if (c > reserved) {
            reserved = c + RESERVE_MICROS;
            store.save(reserved);
        }
        last = c;
        return c;
    }

    /** A store that forgets (tests, and a console whose key directory is read-only). */
    public static Store inMemory() {
        return new Store() {
            private long value;

            @Override
            public long load() {
                return value;
            }

            @Override
            public void save(long reservedUpTo) {
                value = reservedUpTo;
            }
        };
    }
}
