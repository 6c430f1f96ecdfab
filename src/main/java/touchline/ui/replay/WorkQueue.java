package touchline.ui.replay;

import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * One background thread for the slow things a view asks for (opening and scanning a
 * recording, seeking, closing a file), and the hand-over of their results to the FX thread:
 * a task queues FX steps with {@link #handOff}, and the view applies them in its once-per-
 * frame refresh ({@link #drain}), so no task ever calls {@code Platform.runLater}.
 */
final class WorkQueue implements AutoCloseable {

    private final ExecutorService executor;
    private final Queue<Runnable> results = new ConcurrentLinkedQueue<>();
    private final AtomicInteger inFlight = new AtomicInteger();
    private final Consumer<String> onFailure;

    /** @param onFailure FX-side report of a task that threw (its message, for the user) */
    WorkQueue(String name, Consumer<String> onFailure) {
        this.onFailure = onFailure;
        this.executor = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /** Runs {@code task} on the background thread, after the tasks queued before it. */
    void run(Runnable task) {
        inFlight.incrementAndGet();
        executor.execute(() -> {
            try {
                task.run();
            } catch (RuntimeException e) {
                // a task is never allowed to take the console down: the user reads what failed
                String why = e.getMessage() == null ? e.toString() : e.getMessage();
                handOff(() -> onFailure.accept(why));
            } finally {
                inFlight.decrementAndGet();
            }
        });
    }

    /** Queues a step for the FX thread; called from tasks. */
    void handOff(Runnable fxStep) {
        results.add(fxStep);
    }

    /** True while a task is queued or running. */
    boolean busy() {
        return inFlight.get() > 0;
    }

    /** Applies the handed-over steps. FX thread only. */
    void drain() {
        for (Runnable r; (r = results.poll()) != null; ) {
            r.run();
        }
    }

    @Override
    public void close() {
        executor.shutdownNow();
    }
}
