package touchline.transport.nao;

import java.time.Duration;
import java.util.function.BooleanSupplier;

/**
 * Waits for a condition with a deadline instead of sleeping a guessed time. The deadline only
 * stops a test that would hang; it is never shorter than {@link touchline.testing.Await#FLOOR_MILLIS},
 * so a loaded machine does not fail a test (timing budgets belong to the benchmarks).
 */
final class Poll {
    private Poll() {
    }

    /** True as soon as {@code condition} holds; false after {@link touchline.testing.Await#FLOOR_MILLIS}, the policy. */
    static boolean until(BooleanSupplier condition) throws InterruptedException {
        return until(condition, Duration.ofMillis(touchline.testing.Await.FLOOR_MILLIS));
    }

    static boolean until(BooleanSupplier condition, Duration timeout) throws InterruptedException {
        long bound = Math.max(timeout.toMillis(), touchline.testing.Await.FLOOR_MILLIS);
        long end = System.nanoTime() + bound * 1_000_000;
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(5);
        }
        return condition.getAsBoolean();
    }
}
