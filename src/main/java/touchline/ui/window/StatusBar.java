package touchline.ui.window;

import javafx.scene.control.Label;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import touchline.model.TrafficMeter;
import touchline.app.TransportCounts;
import touchline.ui.frame.ConsoleStatus;
import touchline.ui.frame.LatencyProbe;

/**
 * The bottom line: a banner whenever the console is silent and why (match mode, a replay),
 * packets/s and bytes/s in and out (GameController packets included), malformed packets and
 * the requests waiting now, the team's traffic against the league's 1 Mbit/s limit as a small
 * meter, and the UI's own frame rate. Recomputed twice a second from counters (through
 * {@link ConsoleStatus}), never per packet.
 */
public final class StatusBar extends HBox implements touchline.ui.frame.FrameStatus {

    private final touchline.app.LiveField field;
    private final touchline.app.TeamBudget budget;
    private final ConsoleStatus readings;
    /** The banner asks for no more than {@link #SILENCE_MAX_PREF_WIDTH} (whole in its tooltip), so the rates beside it keep some room. */
    private final Label silence = new Label() {
        @Override
        protected double computePrefWidth(double height) {
            return Math.min(super.computePrefWidth(height), SILENCE_MAX_PREF_WIDTH);
        }
    };
    /** The least the match-mode and remote banner is shrunk to, in pixels. */
    static final double SILENCE_MIN_WIDTH = 160;
    /** The most the banner asks for: the match mode's and the replay's first words. */
    static final double SILENCE_MAX_PREF_WIDTH = 360;
    private final Label rates = new Label();
    private final Tooltip ratesTip = new Tooltip();
    private final Label bad = new Label();
    private final Tooltip badTip = new Tooltip();
    private final Label waiting = new Label();
    private final Tooltip waitingTip = new Tooltip();
    private final Tooltip silenceTip = new Tooltip();
    private final BudgetMeter meter = new BudgetMeter();
    private final Label fps = new Label();
    private final Label message = new Label();
    private final Tooltip messageTip = new Tooltip();
    private final Label platform = new Label();
    private long lastMicros;
    private long lastIn;
    private long lastBytesIn;
    private long lastOut;
    private long lastBytesOut;
    private double packetsPerSecond;

    public StatusBar(ConsoleStatus readings, touchline.app.LiveField field, touchline.app.TeamBudget budget) {
        super(10);
        this.field = field;
        this.budget = budget;
        this.readings = readings;
        setId("status-bar");
        setStyle("-fx-padding: 3 8 3 8; -fx-alignment: center-left;");
        rates.setId("status-rates");
        silence.setId("status-silence");
        silence.getStyleClass().add("status-silence");
        // cut with "…" when long (a remote console's server address), the whole text in the tooltip:
        // never wider than the window can be (a 1280-pixel laptop)
        silence.setMinWidth(SILENCE_MIN_WIDTH);
        silence.setTooltip(silenceTip);
        // the counts, the meter and the frame rate keep their words; the banner, the rates, the message
        // and the platform give way on a narrow window, cut with "…" and whole in their tooltips: together
        // the least they take stays inside a 1280-pixel window with the longest texts of play. The bar itself
        // asks the window for no width at all: at the PLAYING whistle under openbox the banner and the
        // meter's "· debug over limit" asked for more than 1280 px and the whole window was laid out
        // wider for seconds, every view and the referee's buttons moved sideways.
        setMinWidth(0);
        rates.setMinWidth(0);
        rates.setTooltip(ratesTip);
        bad.setId("status-malformed");
        bad.setMinWidth(Region.USE_PREF_SIZE);
        bad.setTooltip(badTip);
        waiting.setMinWidth(Region.USE_PREF_SIZE);
        silence.setVisible(false);
        silence.setManaged(false);
        waiting.setId("status-waiting");
        waiting.setTooltip(waitingTip);
        message.setId("status-message");
        message.setMinWidth(0);
        message.setTooltip(messageTip);
        fps.setId("status-fps");
        fps.setMinWidth(Region.USE_PREF_SIZE);
        Region grow = new Region();
        HBox.setHgrow(grow, Priority.ALWAYS);
        // the transport and priority in use: epoll + recvmmsg on Linux, NIO / normal priority as the portable fallback
        touchline.app.RuntimeReport runtime = field.runtime();
        platform.setId("status-platform");
        platform.setText(runtime.portability());
        platform.setMinWidth(0);
        platform.setTooltip(new Tooltip(String.join("\n", runtime.lines())));
        getChildren().addAll(silence, rates, bad, waiting, meter, message, grow, platform, fps);
    }

    public double packetsPerSecond() {
        return packetsPerSecond;
    }

    /** A one-line message (layout saved, command held, ...). */
    public void say(String text) {
        message.setText(text);
        messageTip.setText(text);
    }

    /** The frame pulse stopped because nothing changed: the frame rate reads "idle" until it runs again. */
    @Override
    public void idle() {
        fps.setText("idle");
    }

    @Override
    public void refresh(long nowMicros, double framesPerSecond, LatencyProbe latency) {
        if (nowMicros - lastMicros < 500_000) {
            return;
        }
        TransportCounts c = field.transportCounts();
        double dt = lastMicros == 0 ? 1 : (nowMicros - lastMicros) / 1e6;
        packetsPerSecond = (c.datagramsIn() - lastIn) / dt;
        long out = readings.packetsOut();
        rates.setText(String.format("in %.0f pkt/s %s/s · out %.0f pkt/s %s/s", packetsPerSecond,
                bytes((c.bytesIn() - lastBytesIn) / dt), (out - lastOut) / dt,
                bytes((c.bytesOut() - lastBytesOut) / dt)));
        ratesTip.setText(rates.getText() + "\nDatagrams and bytes per second the console received (robots, team "
                + "messages, GameController) and sent (robots, its own GameController)");
        bad.setText("malformed " + c.malformedIn());
        badTip.setText(bad.getText() + "\nDatagrams the console received and could not read; the Robots view's "
                + "\"Bad sources and notes\" says from where and why");
        bad.setStyle(c.malformedIn() > 0 ? "-fx-text-fill: #cf222e;" : "");
        int waitingNow = readings.waitingNow();
        waiting.setText(waitingNow == 1 ? "1 request waiting now" : waitingNow + " requests waiting now");
        waitingTip.setText("Debug-option changes not yet on the robots because match mode holds the console back; "
                + "they go out when play stops.\n" + readings.heldTotal() + " send attempts held back by match mode "
                + "since the console started (retries included)");
        String why = readings.silence();
        silence.setText(why);
        silenceTip.setText(why + "\nIn match mode the console sends nothing to robots (debug requests wait until play "
                + "stops); the GameController still sends. A replay never sends to the field.");
        silence.setVisible(!why.isEmpty());
        silence.setManaged(!why.isEmpty());
        lastIn = c.datagramsIn();
        lastBytesIn = c.bytesIn();
        lastOut = out;
        lastBytesOut = c.bytesOut();
        lastMicros = nowMicros;
        java.util.Optional<touchline.model.TeamMessageBudget> guard = budget.budget();
        if (guard.isPresent()) {
            showBudget(guard.get().snapshot());
        } else {
            showTraffic();
        }
        double p99 = latency.quantileMillis(0.99);
        fps.setText(String.format("%.0f fps", framesPerSecond) + (Double.isNaN(p99) ? "" : String.format(" · p99 %.0f ms", p99)));
    }

    /** The active profile's limit: the team-message budget of the game (HSL 2026). */
    private void showBudget(touchline.model.TeamMessageBudget.Snapshot s) {
        long total = s.left() >= 0 ? s.left() + s.used() : -1;
        double f = total > 0 ? (double) s.used() / total : 0;
        java.util.List<touchline.model.MatchDebugRule.Reading> over = field.matchRule().broken();
        boolean alarm = s.oversize() > 0 || s.verdict() == touchline.model.TeamMessageBudget.Verdict.EXHAUSTED
                || !over.isEmpty();
        boolean warn = s.verdict() == touchline.model.TeamMessageBudget.Verdict.RUNS_OUT_BEFORE_THE_END;
        StringBuilder tip = new StringBuilder(s.describe()).append("\n\nTeam ").append(s.team())
                .append("'s messages under ").append(s.profile().name()).append(": budget ")
                .append(s.profile().teamMessageBudget().describe()).append(" per game, at most ")
                .append(s.profile().maxTeamMessageBytes().describe()).append(" bytes each. Counted as the "
                        + "GameController counts them: in READY, SET and PLAYING only (not before a GameController "
                        + "is heard, not in INITIAL, not in a penalty shoot-out).");
        for (touchline.model.TeamMessageBudget.Sender r : s.senders()) {
            tip.append(String.format("%n%s: %d messages, %.0f/min, largest %d bytes%s", r.sender(), r.messages(),
                    r.perMinute(), r.largest(), r.oversize() > 0 ? ", " + r.oversize() + " OVERSIZE" : ""));
        }
        over.forEach(o -> tip.append("\nrobot ").append(o.robotId()).append(" in play: ").append(o.describe())
                .append(" (limit: one per ").append(s.profile().debugPeriodMillis().describe()).append(" ms)"));
        meter.show(f, alarm ? BudgetMeter.Level.ALARM : warn ? BudgetMeter.Level.WARN : BudgetMeter.Level.CALM,
                "team " + s.team() + ": " + s.brief() + (over.isEmpty() ? "" : " · debug over limit"), tip.toString());
    }

    /** Without a budget guard: the team's traffic against the 1 Mbit/s limit of the leagues before 2026. */
    private void showTraffic() {
        TrafficMeter.Reading r = field.traffic().read();
        double f = r.fractionOfLimit();
        meter.show(f, f > 1 ? BudgetMeter.Level.ALARM : f > 0.8 ? BudgetMeter.Level.WARN : BudgetMeter.Level.CALM,
                String.format("team %.0f kbit/s (%.0f %%)%s", r.teamBitsPerSecond() / 1000, f * 100,
                        r.overShare().isEmpty() ? "" : " · over share: " + r.overShare()),
                "Team traffic (IP/UDP included) against the 1 Mbit/s league limit (HL 2025; start with --team N "
                        + "for the 2026 team-message budget)" + (r.overShare().isEmpty() ? ""
                        : "\nOver their share: " + r.overShare()));
    }

    static String bytes(double b) {
        return b >= 1e6 ? String.format("%.1f MB", b / 1e6) : b >= 1e3 ? String.format("%.1f kB", b / 1e3) : String.format("%.0f B", b);
    }
}
