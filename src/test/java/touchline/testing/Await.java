package touchline.testing;

import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.fail;

/**
 * Waits for a condition with a deadline (polling), for tests against real processes and sockets.
 * A deadline is a bound for a test that would otherwise hang, not a budget: it is never shorter
 * than {@link #FLOOR_MILLIS}, so a slow or loaded machine (CI beside other work) does not fail a
 * test that would pass a moment later. Budgets are measured by the benchmarks.
 */
public final class Await {

    /** The shortest deadline any wait gets. */
    public static final long FLOOR_MILLIS = 30_000;

    private Await() {
    }

    /**
     * Returns as soon as {@code condition} holds; fails the test naming {@code what} after the floor.
     * The one to use: how long a test may wait is this class's policy, not each test's guess.
     */
    public static void until(String what, BooleanSupplier condition) throws InterruptedException {
        until(what, FLOOR_MILLIS, condition);
    }

    /** Returns as soon as {@code condition} holds; fails the test naming {@code what} after {@code millis}. */
    public static void until(String what, long millis, BooleanSupplier condition) throws InterruptedException {
        long bound = Math.max(millis, FLOOR_MILLIS);
        long deadline = System.nanoTime() + bound * 1_000_000;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("timed out after " + bound + " ms waiting for: " + what);
            }
            Thread.sleep(10);
        }
    }
}
