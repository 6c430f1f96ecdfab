package touchline.cli;

import javafx.application.Platform;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/** Starting JavaFX from a command and running a step on its thread, waiting for the result. */
public final class FxThread {

    private FxThread() { }

    /**
     * How many separate changed areas JavaFX repaints in one frame before it merges them: its 6
     * merged the plot, the debug console and the status bar into boxes painted from the window's
     * root, every background under them included; 12 keeps each view's change its own (the most
     * is 15). A {@code -Dprism.dirtyregioncount} of the user's wins.
     */
    static final String DIRTY_REGIONS = "12";

    public static void startToolkit() throws InterruptedException {
        if (System.getProperty("prism.dirtyregioncount") == null) {
            System.setProperty("prism.dirtyregioncount", DIRTY_REGIONS);
        }
        java.util.concurrent.CountDownLatch up = new java.util.concurrent.CountDownLatch(1);
        Platform.startup(up::countDown);
        up.await(30, TimeUnit.SECONDS);
        Platform.setImplicitExit(false);
    }

    public static <T> T call(Supplier<T> step) throws Exception {
        CompletableFuture<T> f = new CompletableFuture<>();
        Platform.runLater(() -> {
            try {
                f.complete(step.get());
            } catch (Throwable t) {
                f.completeExceptionally(t);
            }
        });
        return f.get(60, TimeUnit.SECONDS);
    }

    public static void run(Runnable step) throws Exception {
        call(() -> {
            step.run();
            return null;
        });
    }

    /** Polls {@code condition} (off the FX thread) until true or the deadline passes. */
    public static boolean await(Supplier<Boolean> condition, long millis) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (System.nanoTime() < deadline) {
            if (condition.get()) {
                return true;
            }
            Thread.sleep(50);
        }
        return condition.get();
    }
}
