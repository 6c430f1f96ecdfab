package touchline.security;

import java.util.function.LongSupplier;

/**
 * The console's strictly increasing counter for the tags it sends: max(last + 1, microseconds
 * since the epoch), so a clock that jumps back still moves forward. Runs of the console never
 * go back either, nor do two consoles of one laptop (the window and {@code touchline options})
 * go back against each other: every counter is taken from a {@link Store} shared by them (a
 * file in the key directory, under a file lock), which hands out one above the last any of them
 * took.
 */
public final class CounterSource {

    /** Where the last counter lives (a file in the key directory; memory in tests). */
    public interface Store {
        /**
         * Atomically, for every process using the store: the greater of {@code atLeast} and one
         * above the last counter taken; kept as the last counter taken.
         */
        long take(long atLeast);
    }

    private final LongSupplier micros;
    private final Store store;
    private long last;

    public CounterSource(LongSupplier micros, Store store) {
        this.micros = micros;
        this.store = store;
    }

    public synchronized long next() {
        long c = store.take(Math.max(last + 1, micros.getAsLong()));
        last = c;
        return c;
    }

    /** A store that forgets (tests, and a console whose key directory is read-only). */
    public static Store inMemory() {
        return new Store() {
            private long value;

            @Override
            public synchronized long take(long atLeast) {
                value = Math.max(atLeast, value + 1);
                return value;
            }
        };
    }
}
