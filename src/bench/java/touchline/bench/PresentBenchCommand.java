package touchline.bench;

import javafx.animation.AnimationTimer;
import javafx.scene.Scene;
import javafx.scene.canvas.Canvas;
import javafx.scene.layout.Pane;
import javafx.scene.paint.Color;
import javafx.stage.Stage;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.cli.FxThread;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * What JavaFX costs for each frame it puts on screen, whatever the frame shows (issue 14's
 * budget, docs/archive/benchmarks-sessions.md "Thirteenth session"). A window of the console's size shows one
 * canvas; in each phase a 2 × 2-pixel square on it changes colour {@code fps} times a second,
 * so each of those frames is drawn and presented but almost nothing is painted. The baseline in
 * the same run: the same window with JavaFX's pulse running and nothing changing. Reported per
 * phase: CPU of the render thread and of the FX thread (% of one core and ms per changed frame).
 * Under the software pipeline (Xvfb, no GPU) JavaFX copies the whole window out for every frame,
 * so this is the floor under any view's own drawing: a window that changes 30 times a second
 * costs at least this much, however little changes.
 */
@Command(name = "present", mixinStandardHelpOptions = true,
        description = "JavaFX's own cost per frame on screen (a 2x2-px change), against a window that changes nothing.")
public final class PresentBenchCommand implements Callable<Integer> {

    @Option(names = "--seconds", defaultValue = "20", description = "seconds per phase (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--fps", split = ",", defaultValue = "30,15,10",
            description = "changed frames a second, one phase each (default ${DEFAULT-VALUE})")
    List<Integer> rates;

    @Option(names = "--sizes", split = ",", defaultValue = "1280x720,640x360",
            description = "window sizes, each with a baseline and every --fps phase (default ${DEFAULT-VALUE})")
    List<String> sizes;

    private final ThreadMXBean mx = ManagementFactory.getThreadMXBean();

    /** One phase's figures. */
    record Phase(String size, String what, double seconds, long changedFrames, double renderPct, double fxPct) {
        String row(Phase baseline) {
            double perFrame = changedFrames == 0 ? 0 : (renderPct + fxPct) * 10 * seconds / changedFrames;
            String ratio = baseline == null || this == baseline ? "1.00"
                    : String.format(Locale.ROOT, "%.2f", (renderPct + fxPct) / Math.max(0.01, baseline.renderPct + baseline.fxPct));
            return String.format(Locale.ROOT, "| %s | %s | %.1f | %d | %.1f %% | %.1f %% | %.1f %% | %s | %s |", size, what, seconds,
                    changedFrames, renderPct, fxPct, renderPct + fxPct,
                    changedFrames == 0 ? "—" : String.format(Locale.ROOT, "%.2f ms", perFrame), ratio);
        }
    }

    @Override
    public Integer call() throws Exception {
        FxThread.startToolkit();
        Canvas canvas = new Canvas(64, 64);
        Stage stage = FxThread.call(() -> {
            Stage s = new Stage();
            s.setTitle("touchline bench present");
            s.setScene(new Scene(new Pane(canvas)));
            return s;
        });
        Changer changer = new Changer(canvas);
        System.out.println("| window | phase | s | changed frames | render thread | FX thread | both | per changed frame | both / baseline |");
        System.out.println("|---|---|---|---|---|---|---|---|---|");
        for (String size : sizes) {
            String[] wh = size.toLowerCase(Locale.ROOT).split("x");
            int w = Integer.parseInt(wh[0].trim());
            int h = Integer.parseInt(wh[1].trim());
            FxThread.run(() -> {
                stage.setWidth(w);
                stage.setHeight(h);
                stage.show();
                changer.start();
            });
            changer.every(0);
            Thread.sleep(3_000); // shown, sized, the JIT warm for the first phase
            Phase baseline = measure(size, "pulse only, nothing changes", changer, 0);
            System.out.println(baseline.row(baseline));
            for (int fps : rates) {
                Phase p = measure(size, fps + " changed frames/s", changer, fps);
                System.out.println(p.row(baseline));
            }
        }
        FxThread.run(() -> {
            changer.stop();
            stage.close();
        });
        return 0;
    }

    private Phase measure(String size, String what, Changer changer, int fps) throws Exception {
        changer.every(fps == 0 ? 0 : Math.max(1, Math.round(60f / fps)));
        Thread.sleep(1_000); // settle into the new rate
        long r0 = cpu("QuantumRenderer-0");
        long f0 = cpu("JavaFX Application Thread");
        long c0 = changer.changed();
        long t0 = System.nanoTime();
        Thread.sleep(seconds * 1_000L); // a duration measured, not a condition awaited
        double secs = (System.nanoTime() - t0) / 1e9;
        long r = cpu("QuantumRenderer-0") - r0;
        long f = cpu("JavaFX Application Thread") - f0;
        return new Phase(size, what, secs, changer.changed() - c0, r / 1e7 / secs, f / 1e7 / secs);
    }

    private long cpu(String thread) {
        for (ThreadInfo t : mx.dumpAllThreads(false, false)) {
            if (t.getThreadName().equals(thread)) {
                return mx.getThreadCpuTime(t.getThreadId());
            }
        }
        throw new IllegalStateException("no thread " + thread + " (is this JavaFX's software or es2 pipeline?)");
    }

    /** Changes a 2 × 2 square every n-th pulse (0: never); JavaFX pulses 60 times a second while it runs. */
    private static final class Changer extends AnimationTimer {
        private final Canvas canvas;
        private volatile int every;
        private volatile long changed;
        private long pulses;

        Changer(Canvas canvas) {
            this.canvas = canvas;
        }

        void every(int n) {
            every = n;
        }

        long changed() {
            return changed;
        }

        @Override
        public void handle(long now) {
            pulses++;
            int n = every;
            if (n > 0 && pulses % n == 0) {
                changed++;
                canvas.getGraphicsContext2D().setFill(Color.gray((changed % 2) * 0.5 + 0.25));
                canvas.getGraphicsContext2D().fillRect(0, 0, 2, 2);
            }
        }
    }
}
