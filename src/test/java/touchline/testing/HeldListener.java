package touchline.testing;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * A listener that holds the thread calling it (a runtime's owner) until {@link #release()}: for
 * tests that a face's call only enqueues while the owner is busy.
 */
public final class HeldListener<T> implements Consumer<T> {

    private final CountDownLatch held = new CountDownLatch(1);
    private final CountDownLatch release = new CountDownLatch(1);

    @Override
    public void accept(T value) {
        held.countDown();
        try {
            release.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Waits until a thread is held here; false when none came within {@link Await#FLOOR_MILLIS}. */
    public boolean awaitHeld() throws InterruptedException {
        return held.await(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
    }

    public void release() {
        release.countDown();
    }
}
