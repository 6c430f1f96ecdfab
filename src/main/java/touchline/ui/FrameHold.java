package touchline.ui;

import javafx.application.Platform;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;

/**
 * Lets the frame pulse sleep between the frames its {@link FrameCap} allows. JavaFX pulses 60
 * times a second while any frame timer runs, and every pulse walks the whole scene (its CSS,
 * layout and bounds passes) even when no view may draw in it; with the standard cap of 30, every
 * other pulse was such a walk. Instead the pulse stops after a frame and a daemon thread asks the
 * FX thread to start it again shortly before the next frame is due. At most one wake-up is
 * pending; a new hold replaces it.
 */
final class FrameHold implements AutoCloseable {

    private ScheduledExecutorService timer;
    private ScheduledFuture<?> pending;

    /** Runs {@code resume} on the FX thread after {@code nanos}. FX thread. */
    void resumeIn(long nanos, Runnable resume) {
        cancel();
        if (timer == null) {
            timer = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "touchline-ui-hold");
                t.setDaemon(true);
                return t;
            });
        }
        pending = timer.schedule(() -> Platform.runLater(resume), nanos, TimeUnit.NANOSECONDS);
    }

    /** Drops the pending wake-up, if any. FX thread. */
    void cancel() {
        if (pending != null) {
            pending.cancel(false);
            pending = null;
        }
    }

    @Override
    public void close() {
        cancel();
        if (timer != null) {
            timer.shutdownNow();
        }
    }
}
