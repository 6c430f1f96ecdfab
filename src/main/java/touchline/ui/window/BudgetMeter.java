package touchline.ui.window;

import javafx.scene.control.ContentDisplay;
import javafx.scene.control.Label;
import javafx.scene.control.ProgressBar;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.Region;

/**
 * The status bar's team meter: a bar and a short text in one label that never gives up width
 * ("team 13: 3 used · 11997 left · lasts the game" under the 2026 budget, the kbit/s against the
 * 1 Mbit/s limit before it), with one tooltip over the whole of it that says the rules and every
 * sender. The longer details go to the tooltip, never into the place, so the meter reads the same
 * at 1280 pixels in play as in a wide window at rest.
 */
final class BudgetMeter extends Label {

    private static final String CALM = "-fx-accent: #2da44e;";
    private static final String WARN = "-fx-accent: #bf8700;";
    private static final String ALARM = "-fx-accent: #cf222e;";

    private final ProgressBar bar = new ProgressBar(0);
    private final Tooltip tip = new Tooltip();

    BudgetMeter() {
        setId("status-meter");
        bar.setPrefWidth(90);
        bar.setMinWidth(90);
        // the tooltip belongs to the label, bar and text alike: it shows wherever the pointer is
        bar.setMouseTransparent(true);
        setGraphic(bar);
        setContentDisplay(ContentDisplay.LEFT);
        setGraphicTextGap(6);
        setMinWidth(Region.USE_PREF_SIZE);
        tip.setWrapText(true);
        tip.setMaxWidth(640);
        setTooltip(tip);
    }

    /** Shows a reading: the share used (0..1), its level, the short text and the whole story. */
    void show(double used, Level level, String text, String details) {
        bar.setProgress(Math.min(1, Math.max(0, used)));
        bar.setStyle(level == Level.ALARM ? ALARM : level == Level.WARN ? WARN : CALM);
        setText(text);
        setStyle(level == Level.ALARM ? "-fx-text-fill: #cf222e;" : level == Level.WARN ? "-fx-text-fill: #bf8700;" : "");
        tip.setText(details);
    }

    String details() {
        return tip.getText();
    }

    /** How the reading looks: calm, a warning (runs out before the end), an alarm (exhausted, oversize). */
    enum Level { CALM, WARN, ALARM }
}
