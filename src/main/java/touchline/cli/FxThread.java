package touchline.cli;

import javafx.application.Platform;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

/** Starting JavaFX from a command and running a step on its thread, waiting for the result. */
public final class FxThread {

    private FxThread() { }

    public static void startToolkit() throws InterruptedException {
        new touchline.ui.render.RenderDefaults().apply();
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
