package touchline.ui.replay;

import javafx.scene.Node;
import javafx.scene.canvas.GraphicsContext;
import javafx.scene.control.Tooltip;
import javafx.scene.input.MouseEvent;
import javafx.scene.paint.Color;
import javafx.util.Duration;
import touchline.record.PlayerState;
import touchline.record.TimelineEvent;
import touchline.ui.render.ResizableCanvas;

import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.LongConsumer;

/**
 * The recording as a bar: played part, loop range, a coloured tick per event (goal, state
 * change, robot lost; the tooltip names the one under the mouse) and the play head. A click
 * or drag asks for a seek to the time under the mouse; while dragging the head follows the
 * mouse at once, whatever the player reports.
 */
final class TimelineCanvas {

    static final double PAD = 12;
    static final Color GOAL = Color.web("#d4a72c");
    static final Color STATE_CHANGE = Color.web("#2f81f7");
    static final Color ROBOT_LOST = Color.web("#cf222e");
    static final Color PENALTY = Color.web("#e16f24");

    private final ResizableCanvas pane = new ResizableCanvas(this::draw);
    private final Tooltip tip = new Tooltip();
    private final LongConsumer seek;
    private PlayerState state;
    private List<TimelineEvent> events = List.of();
    private long dragMicros = -1;
    private long drawnPosition = Long.MIN_VALUE;

    TimelineCanvas(LongConsumer seek) {
        this.seek = seek;
        pane.setId("replay-timeline");
        pane.setPrefSize(600, 64);
        pane.setMinHeight(56);
        pane.setMaxHeight(72);
        tip.setShowDelay(Duration.millis(150));
        Tooltip.install(pane, tip);
        pane.setOnMousePressed(this::drag);
        pane.setOnMouseDragged(this::drag);
        pane.setOnMouseReleased(e -> {
            drag(e);
            dragMicros = -1;
        });
        pane.setOnMouseMoved(e -> tip.setText(tooltipAt(e.getX())));
    }

    Node node() {
        return pane;
    }

    /** Shows this state and these events; redraws only when something visible changed. */
    void show(PlayerState s, List<TimelineEvent> ev) {
        boolean changed = ev != events || s == null != (state == null) || s != null && (state == null
                || s.positionMicros() != drawnPosition || s.loopFromMicros() != state.loopFromMicros()
                || s.loopToMicros() != state.loopToMicros() || s.startMicros() != state.startMicros());
        state = s;
        events = ev;
        if (changed) {
            draw();
        }
    }

    /** The x of {@code micros} on a bar {@code width} wide. */
    static double xAt(long micros, long start, long end, double width) {
        double f = end <= start ? 0 : (double) (micros - start) / (end - start);
        return PAD + Math.max(0, Math.min(1, f)) * (width - 2 * PAD);
    }

    /** The time under {@code x} on a bar {@code width} wide, clamped to the recording. */
    static long timeAt(double x, long start, long end, double width) {
        double f = (x - PAD) / Math.max(1, width - 2 * PAD);
        return start + Math.round(Math.max(0, Math.min(1, f)) * (end - start));
    }

    /** The x of a time on this canvas now. */
    private double xOf(long micros) {
        return state == null ? PAD : xAt(micros, state.startMicros(), state.endMicros(), pane.getWidth());
    }

    static Color colour(TimelineEvent.Type type) {
        return switch (type) {
            case GOAL -> GOAL;
            case STATE_CHANGE -> STATE_CHANGE;
            case PENALTY -> PENALTY;
            case ROBOT_LOST -> ROBOT_LOST;
        };
    }

    private void drag(MouseEvent e) {
        if (state == null) {
            return;
        }
        dragMicros = timeAt(e.getX(), state.startMicros(), state.endMicros(), pane.getWidth());
        seek.accept(dragMicros);
        draw();
    }

    private String tooltipAt(double x) {
        if (state == null) {
            return "Open a recording to see its timeline";
        }
        Optional<TimelineEvent> near = events.stream()
                .filter(ev -> Math.abs(xOf(ev.timeMicros()) - x) <= 4)
                .min((a, b) -> Double.compare(Math.abs(xOf(a.timeMicros()) - x), Math.abs(xOf(b.timeMicros()) - x)));
        long t = timeAt(x, state.startMicros(), state.endMicros(), pane.getWidth());
        return near.map(ev -> clock(ev.timeMicros() - state.startMicros()) + "  " + label(ev))
                .orElse(clock(t - state.startMicros()) + " — click to seek");
    }

    static String label(TimelineEvent ev) {
        String what = switch (ev.type()) {
            case GOAL -> "Goal";
            case STATE_CHANGE -> "State change";
            case PENALTY -> "Penalty";
            case ROBOT_LOST -> "Robot lost";
        };
        return what + (ev.robotId() >= 0 ? " (robot " + ev.robotId() + ")" : "")
                + (ev.label() == null || ev.label().isEmpty() ? "" : ": " + ev.label());
    }

    /** m:ss.s of a duration in microseconds (h:mm:ss past an hour). */
    static String clock(long micros) {
        long tenths = Math.max(0, micros) / 100_000;
        long s = tenths / 10;
        return s >= 3600 ? String.format(Locale.ROOT, "%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60)
                : String.format(Locale.ROOT, "%d:%02d.%d", s / 60, s % 60, tenths % 10);
    }

    private void draw() {
        double w = pane.getWidth();
        double h = pane.getHeight();
        GraphicsContext g = pane.canvas().getGraphicsContext2D();
        g.clearRect(0, 0, w, h);
        double barTop = h * 0.35;
        double barH = h * 0.3;
        g.setFill(Color.gray(0.5, 0.25));
        g.fillRoundRect(PAD, barTop, Math.max(0, w - 2 * PAD), barH, 6, 6);
        if (state == null) {
            return;
        }
        long start = state.startMicros();
        long end = state.endMicros();
        long pos = dragMicros >= 0 ? dragMicros : state.positionMicros();
        drawnPosition = state.positionMicros();
        if (state.loopFromMicros() >= 0) {
            double a = xAt(state.loopFromMicros(), start, end, w);
            double b = xAt(state.loopToMicros(), start, end, w);
            g.setFill(Color.web("#8250df", 0.3));
            g.fillRect(a, barTop - 6, b - a, barH + 12);
        }
        double px = xAt(pos, start, end, w);
        g.setFill(Color.web("#2da44e", 0.55));
        g.fillRoundRect(PAD, barTop, px - PAD, barH, 6, 6);
        for (TimelineEvent ev : events) {
            double x = Math.round(xAt(ev.timeMicros(), start, end, w)) + 0.5;
            g.setStroke(colour(ev.type()));
            g.setLineWidth(ev.type() == TimelineEvent.Type.GOAL ? 3 : 2);
            double top = ev.type() == TimelineEvent.Type.ROBOT_LOST ? barTop + barH * 0.5 : 2;
            g.strokeLine(x, top, x, ev.type() == TimelineEvent.Type.ROBOT_LOST ? h - 2 : barTop + barH * 0.5);
        }
        g.setFill(Color.gray(0.5));
        g.fillRect(px - 1.5, 0, 3, h);
        g.fillPolygon(new double[]{px - 6, px + 6, px}, new double[]{0, 0, 8}, 3);
    }
}
