package touchline.ui.referee;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.TextArea;
import javafx.scene.layout.BorderPane;
import touchline.app.game.MonitorReport;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.window.ViewContext;

import java.util.List;
import java.util.Optional;

/**
 * Each robot as the field's HSL GameController sees it: its forwarded return packet (fallen,
 * pose, ball) and liveness, when the console registered as a monitor ({@code --gc-monitor
 * HOST}). Pulls twice a second; the lines are the same as {@code listen}'s.
 */
public final class GcRobotsView implements View {

    private final ViewContext context;
    private final Label status = new Label();
    private final TextArea lines = new TextArea();
    private final BorderPane root = new BorderPane();
    private List<String> shown = List.of();

    public GcRobotsView(ViewContext context) {
        this.context = context;
        lines.setEditable(false);
        lines.setId("gc-robots-text");
        lines.setStyle("-fx-font-family: monospace;");
        status.setId("gc-robots-status");
        status.setStyle("-fx-padding: 4 8 4 8;");
        root.setTop(status);
        root.setCenter(lines);
    }

    private long shownMicros = Long.MIN_VALUE / 2;

    @Override
    public Node node() {
        return root;
    }

    @Override
    public void refresh(FrameContext frame) {
        if (frame.nowMicros() - shownMicros < 500_000) {
            return; // twice a second (frames are few when the window is quiet)
        }
        shownMicros = frame.nowMicros();
        Optional<MonitorReport> monitor = context.referee().monitorReport(context.field().clock().nowMicros() / 1000);
        if (monitor.isEmpty()) {
            status.setText("Not a monitor of the field's GameController: start with --gc-monitor HOST to see the "
                    + "robots as the referee sees them.");
            return;
        }
        List<String> now = monitor.get().lines();
        status.setText("The field's GameController sees " + monitor.get().robots() + " robot(s)");
        if (!now.equals(shown)) {
            shown = now;
            lines.setText(String.join("\n", now));
        }
    }
}
