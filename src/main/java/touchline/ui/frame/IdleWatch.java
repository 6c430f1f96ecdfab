package touchline.ui.frame;

import javafx.application.Platform;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.LongSupplier;

/**
 * Wakes the idle window: while the frame pulse is stopped because nothing changed, a daemon
 * thread reads the console's change counter a few times a second and, when it moved, asks the
 * FX thread once to start the pulse again. Never per message, and nothing on the FX thread
 * while nothing changes.
 */
final class IdleWatch implements AutoCloseable {

    /** How often the idle window looks for a change: the most a change waits to be shown. */
    static final long POLL_MILLIS = 250;

    private final LongSupplier changes;
    private final Runnable wake;
    private ScheduledExecutorService poller;
    private volatile boolean watching;
    private volatile long idleAt;

    IdleWatch(LongSupplier changes, Runnable wake) {
        this.changes = changes;
        this.wake = wake;
    }

    /** The pulse stopped with the counter at {@code reading}: wake it when the counter moves. FX thread. */
    void watchFrom(long reading) {
        idleAt = reading;
        watching = true;
        if (poller == null) {
            poller = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "touchline-ui-idle");
                t.setDaemon(true);
                return t;
            });
            poller.scheduleWithFixedDelay(this::poll, POLL_MILLIS, POLL_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    /** The pulse runs again (or must not be woken, e.g. minimised): stop looking. FX thread. */
    void stopWatching() {
        watching = false;
    }

    private void poll() {
        if (watching && changes.getAsLong() != idleAt) {
            watching = false; // one wake-up per change, however long the FX thread takes to run it
            Platform.runLater(wake);
        }
    }

    @Override
    public void close() {
        watching = false;
        if (poller != null) {
            poller.shutdownNow();
        }
    }
}
