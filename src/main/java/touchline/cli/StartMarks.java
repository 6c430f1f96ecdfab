package touchline.cli;

import touchline.transport.MicrosClock;
import touchline.model.RobotPresence;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The console's two start marks on standard error, once each: the window shown and the first
 * robot's data in the model, with the milliseconds since the JVM started. {@code ./touchline bench
 * start} reads them; a user sees how long the start took. With {@value #TRAINING_PROPERTY}{@code =N}
 * (the class-data-sharing training run of the launcher and of the package, docs/archive/benchmarks-sessions.md
 * "Start") the window closes itself after N frames ({@code ConsoleWindow.closeAfterFrames}), so the JVM exits normally and writes its
 * archive: 1 frame archives what the window needs before its views, more frames the views too.
 */
final class StartMarks implements RobotPresence {

    static final String WINDOW_MARK = "touchline: window shown";
    static final String DATA_MARK = "touchline: first robot's data";
    static final String TRAINING_PROPERTY = "touchline.cds.training";

    /** Frames after which a training run closes its window; 0 (no training) when the property is unset. */
    static int trainingFrames() {
        return Integer.getInteger(TRAINING_PROPERTY, 0);
    }

    private final PrintStream out;
    private final long jvmStartMillis;
    private final MicrosClock clock;
    private final AtomicBoolean window = new AtomicBoolean();
    private final AtomicBoolean data = new AtomicBoolean();

    /** @param clock the console's wall clock */
    StartMarks(PrintStream out, MicrosClock clock) {
        this(out, ManagementFactory.getRuntimeMXBean().getStartTime(), clock);
    }

    StartMarks(PrintStream out, long jvmStartMillis, MicrosClock clock) {
        this.out = out;
        this.jvmStartMillis = jvmStartMillis;
        this.clock = clock;
    }

    void windowShown() {
        mark(window, WINDOW_MARK);
    }

    @Override
    public void cameOnline(int robotId, boolean firstTime) {
        mark(data, DATA_MARK + " (robot " + robotId + ")");
    }

    @Override
    public void wentOffline(int robotId) {
        // only the first arrival is a start mark
    }

    private void mark(AtomicBoolean once, String what) {
        if (once.compareAndSet(false, true)) {
            out.println(what + " " + (clock.nowMicros() / 1000 - jvmStartMillis) + " ms after the JVM started");
        }
    }
}
