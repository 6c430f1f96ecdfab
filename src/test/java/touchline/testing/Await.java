package touchline.testing;

import java.util.function.BooleanSupplier;

import static org.junit.jupiter.api.Assertions.fail;

/** Waits for a condition with a deadline (polling), for tests against real processes and sockets. */
public final class Await {

    private Await() {
    }

    /** Returns as soon as {@code condition} holds; fails the test naming {@code what} after {@code millis}. */
    public static void until(String what, long millis, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + millis * 1_000_000;
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                fail("timed out after " + millis + " ms waiting for: " + what);
            }
            Thread.sleep(10);
        }
    }
}
