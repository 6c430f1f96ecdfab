package touchline.testing;

import touchline.app.game.GameRuntime;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * Holds a {@link GameRuntime}'s owner thread in a listener from its next change until closed:
 * a test's way to make the owner busy (no event runs meanwhile) without timing anything.
 */
public final class HeldOwner implements AutoCloseable {

    private final CountDownLatch held = new CountDownLatch(1);
    private final CountDownLatch release = new CountDownLatch(1);

    /** Holds {@code owner} at the next change it publishes. */
    public HeldOwner(GameRuntime owner) {
        owner.addListener(s -> {
            held.countDown();
            try {
                release.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
    }

    /** Whether the owner is held; false when it was not within {@link Await#FLOOR_MILLIS}. */
    public boolean awaitHeld() throws InterruptedException {
        return held.await(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** Whether the owner is still held (not yet released). */
    public boolean holding() {
        return release.getCount() > 0;
    }

    /** Lets the owner go on. */
    @Override
    public void close() {
        release.countDown();
    }
}
