package touchline.ui.frame;

import javafx.animation.AnimationTimer;
/**
 * The one place the UI reads the model: once per JavaFX pulse it refreshes every open view
 * and the status bar. 10 000 messages a second cost the FX thread the same as 10, because
 * nothing is pushed to it. Each view is pulled through its {@link ViewFrame}, which keeps a
 * view's faults inside that view.
 * <p>
 * Light on the laptop: a frame in which the console's change counter ({@link ConsoleChanges})
 * did not move and no key or mouse reached the window pulls no view, except twice a second for
 * what ages without a change (an option's "streaming" flag), and while data streams at most as
 * often as its {@link FrameCap} lets it, 30 times a second unless the user chose otherwise
 * ({@code console --max-fps}; input is followed at once). After {@link #IDLE_NANOS} without
 * a change (and at least {@link #IDLE_FRAMES} frames) the pulse stops altogether and the window
 * is idle until {@link IdleWatch} sees the counter move or the user touches the window. A
 * minimised (iconified) window does no frame work at all; it catches up when shown again.
 */
public final class FramePulse extends AnimationTimer {

    /** Quiet time after which the pulse stops: longer than the option list's 2-s streaming window. */
    static final long IDLE_NANOS = 3_000_000_000L;
    /** ... and quiet frames: a slow machine still gets its catch-up frames first. */
    static final int IDLE_FRAMES = 90;
    /** Frames between the catch-up pulls of a quiet window (about twice a second). */
    static final int CATCH_UP_FRAMES = 30;
    /**
     * While data streams, how often the views may pull: a datagram in every frame would otherwise
     * redraw the consoles 60 times a second, most of the console's CPU on a laptop, for no
     * difference a person can read. Input is followed in the same frame.
     */
    private final FrameCap cap;

    private final java.util.function.Supplier<? extends Iterable<PulledView>> views;
    private final FrameStatus status;
    private final touchline.transport.MicrosClock clock;
    private final LatencyProbe latency = new LatencyProbe();
    private final FrameContext frame = new FrameContext(latency);
    private final Runnable extra;
    private final java.util.function.LongSupplier changes;
    private final IdleWatch watch;
    private final java.util.Map<String, Long> refreshNanos = new java.util.TreeMap<>();
    private long frames;
    private long workFrames;
    private long windowStart;
    private long windowFrames;
    private double fps;
    private long seenChanges = Long.MIN_VALUE;
    private boolean input;
    private long quietSinceNanos;
    private int quietFrames;
    private boolean running;
    private boolean iconified;
    private boolean closed;
    private long workNanos;

    public FramePulse(java.util.function.Supplier<? extends Iterable<PulledView>> views, FrameStatus status, touchline.transport.MicrosClock clock, Runnable extra,
                      java.util.function.LongSupplier changes, FrameCap cap) {
        this.cap = cap;
        this.views = views;
        this.status = status;
        this.clock = clock;
        this.extra = extra;
        this.changes = changes;
        this.watch = new IdleWatch(changes, this::wake);
    }

    @Override
    public void start() {
        if (closed || iconified) {
            return;
        }
        watch.stopWatching();
        running = true;
        windowStart = 0;
        windowFrames = 0;
        quietSinceNanos = 0;
        quietFrames = 0;
        super.start();
    }

    @Override
    public void stop() {
        running = false;
        super.stop();
    }

    @Override
    public void handle(long nowNanos) {
        frames++;
        windowFrames++;
        if (windowStart == 0) {
            windowStart = nowNanos;
        } else if (nowNanos - windowStart >= 1_000_000_000L) {
            fps = windowFrames * 1e9 / (nowNanos - windowStart);
            windowStart = nowNanos;
            windowFrames = 0;
        }
        long c = changes.getAsLong();
        boolean changed = c != seenChanges || input;
        if (changed && !input && cap.holdsBack(nowNanos, workNanos)) {
            return; // a data change shown in a frame or two, with the next ones it brings
        }
        input = false;
        if (changed || quietSinceNanos == 0) {
            seenChanges = c;
            quietSinceNanos = nowNanos;
            quietFrames = 0;
        } else {
            quietFrames++;
        }
        boolean goIdle = !changed && quietFrames >= IDLE_FRAMES && nowNanos - quietSinceNanos >= IDLE_NANOS;
        if (changed || quietFrames % CATCH_UP_FRAMES == 0 || goIdle) {
            workNanos = nowNanos;
            work();
        }
        if (goIdle) {
            stop();
            status.idle();
            watch.watchFrom(c);
        }
    }

    /** One frame's work: every view on screen pulls what changed, then the status bar. */
    private void work() {
        workFrames++;
        frame.begin(clock.nowMicros());
        extra.run();
        for (PulledView v : views.get()) {
            if (!showing(v.frame().view().node())) {
                continue; // a tab behind another one catches up the moment it is selected
            }
            long t0 = System.nanoTime();
            v.frame().pull(frame);
            refreshNanos.merge(v.id(), System.nanoTime() - t0, Long::sum);
        }
        status.refresh(frame.nowMicros(), fps, latency);
    }

    /** The console changed or the user did something: run again if idle (not while minimised). FX thread. */
    public void wake() {
        if (!running) {
            start();
        }
    }

    /** A key, mouse or scroll event reached the window: its views may want to follow it. FX thread. */
    public void input() {
        input = true;
        wake();
    }

    /** The window was minimised (true) or shown again (false). FX thread. */
    public void iconified(boolean minimised) {
        iconified = minimised;
        if (minimised) {
            stop();
            watch.stopWatching();
        } else {
            input = true; // a full frame at once: what arrived meanwhile
            wake();
        }
    }

    /** The window closed: stops the pulse and the idle watch for good. */
    public void close() {
        closed = true;
        stop();
        watch.close();
    }

    /** True while the pulse runs; false when idle, minimised or closed. */
    public boolean running() {
        return running;
    }

    /** On screen: in a shown window and neither it nor any ancestor hidden. */
    public static boolean showing(javafx.scene.Node node) {
        if (node.getScene() == null || node.getScene().getWindow() == null || !node.getScene().getWindow().isShowing()) {
            return false;
        }
        for (javafx.scene.Node n = node; n != null; n = n.getParent()) {
            if (!n.isVisible()) {
                return false;
            }
        }
        return true;
    }

    /** Pulses so far (each call of the timer, whether it found work or not). */
    public long frames() {
        return frames;
    }

    /** Pulses that pulled the views (a change, user input, a catch-up, or the last before idling). */
    public long workFrames() {
        return workFrames;
    }

    public double fps() {
        return fps;
    }

    /** How often the views may pull while data streams. */
    public FrameCap cap() {
        return cap;
    }

    /** Time spent in each view's refresh since the last call, by view ID, and resets it (profiling). */
    public java.util.Map<String, Long> takeRefreshNanos() {
        java.util.Map<String, Long> out = new java.util.TreeMap<>(refreshNanos);
        refreshNanos.clear();
        return out;
    }

    public LatencyProbe latency() {
        return latency;
    }
}
