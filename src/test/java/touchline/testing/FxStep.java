package touchline.testing;

import org.testfx.util.WaitForAsyncUtils;

import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

/**
 * One step of a test on the JavaFX thread: its result, or its exception rethrown in the test. The
 * deadline bounds a test that would otherwise hang; it is not a budget.
 */
public final class FxStep {

    private FxStep() {
    }

    /** Runs {@code step} on the FX thread and returns what it returned (30 s at most). */
    public static <T> T fx(Callable<T> step) throws Exception {
        return WaitForAsyncUtils.asyncFx(step).get(30, TimeUnit.SECONDS);
    }
}
