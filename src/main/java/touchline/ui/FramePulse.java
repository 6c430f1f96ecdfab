package touchline.ui;

import javafx.animation.AnimationTimer;
/**
 * The one place the UI reads the model: once per JavaFX pulse it refreshes every open view
 * and the status bar. 10 000 messages a second cost the FX thread the same as 10, because
 * nothing is pushed to it. Each view is pulled through its {@link ViewFrame}, which keeps a
 * view's faults inside that view.
 */
public final class FramePulse extends AnimationTimer {

    private final Shell shell;
    private final StatusBar status;
    private final touchline.transport.MicrosClock clock;
    private final LatencyProbe latency = new LatencyProbe();
    private final FrameContext frame = new FrameContext(latency);
    private final Runnable extra;
    private final java.util.Map<String, Long> refreshNanos = new java.util.TreeMap<>();
    private long frames;
    private long windowStart;
    private long windowFrames;
    private double fps;

    public FramePulse(Shell shell, StatusBar status, touchline.transport.MicrosClock clock, Runnable extra) {
        this.shell = shell;
        this.status = status;
        this.clock = clock;
        this.extra = extra;
    }

    @Override
    public void handle(long nowNanos) {
        frame.begin(clock.nowMicros());
        frames++;
        windowFrames++;
        if (windowStart == 0) {
            windowStart = nowNanos;
        } else if (nowNanos - windowStart >= 1_000_000_000L) {
            fps = windowFrames * 1e9 / (nowNanos - windowStart);
            windowStart = nowNanos;
            windowFrames = 0;
        }
        extra.run();
        for (Shell.OpenView v : shell.openViews()) {
            if (!showing(v.view().node())) {
                continue; // a tab behind another one catches up the moment it is selected
            }
            long t0 = System.nanoTime();
            v.frame().pull(frame);
            refreshNanos.merge(v.spec().id(), System.nanoTime() - t0, Long::sum);
        }
        status.refresh(frame.nowMicros(), fps, latency);
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

    public long frames() {
        return frames;
    }

    public double fps() {
        return fps;
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
