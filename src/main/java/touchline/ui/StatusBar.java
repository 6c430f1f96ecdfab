package touchline.ui;

import javafx.scene.control.Label;
import javafx.scene.control.ProgressBar;
import javafx.scene.control.Tooltip;
import javafx.scene.layout.HBox;
import javafx.scene.layout.Priority;
import javafx.scene.layout.Region;
import touchline.model.TrafficMeter;
import touchline.app.TransportCounts;

/**
 * The bottom line: a banner whenever the console is silent and why (match mode, a replay),
 * packets/s and bytes/s in and out (GameController packets included), malformed packets and
 * the requests waiting now, the team's traffic against the league's 1 Mbit/s limit as a small
 * meter, and the UI's own frame rate. Recomputed twice a second from counters (through
 * {@link ConsoleStatus}), never per packet.
 */
public final class StatusBar extends HBox {

    private final touchline.app.Console console;
    private final ConsoleStatus readings;
    private final Label silence = new Label();
    /** The least the match-mode and remote banner is shrunk to, in pixels. */
    static final double SILENCE_MIN_WIDTH = 260;
    private final Label rates = new Label();
    private final Label bad = new Label();
    private final Label waiting = new Label();
    private final Tooltip waitingTip = new Tooltip();
    private final Tooltip silenceTip = new Tooltip();
    private final ProgressBar meter = new ProgressBar(0);
    private final Label meterText = new Label();
    private final Label meterName = new Label("Team");
    private final Tooltip meterTip = new Tooltip("Team traffic (IP/UDP included) against the 1 Mbit/s league limit");
    private final Label fps = new Label();
    private final Label message = new Label();
    private final Label platform = new Label();
    private long lastMicros;
    private long lastIn;
    private long lastBytesIn;
    private long lastOut;
    private long lastBytesOut;
    private double packetsPerSecond;

    public StatusBar(touchline.app.Console console) {
        super(12);
        this.console = console;
        this.readings = new ConsoleStatus(console);
        setId("status-bar");
        setStyle("-fx-padding: 3 8 3 8; -fx-alignment: center-left;");
        meter.setPrefWidth(120);
        meter.setTooltip(meterTip);
        rates.setId("status-rates");
        silence.setId("status-silence");
        silence.getStyleClass().add("status-silence");
        // cut with "…" when long (a remote console's server address), the whole text in the tooltip:
        // never wider than the window can be (a 1280-pixel laptop)
        silence.setMinWidth(SILENCE_MIN_WIDTH);
        silence.setTooltip(silenceTip);
        // the counts keep their words; the meter's text and messages give way on a narrow window
        rates.setMinWidth(Region.USE_PREF_SIZE);
        bad.setMinWidth(Region.USE_PREF_SIZE);
        waiting.setMinWidth(Region.USE_PREF_SIZE);
        silence.setVisible(false);
        silence.setManaged(false);
        waiting.setId("status-waiting");
        waiting.setTooltip(waitingTip);
        meterText.setId("status-meter");
        meterName.setMinWidth(Region.USE_PREF_SIZE);
        Region grow = new Region();
        HBox.setHgrow(grow, Priority.ALWAYS);
        // the transport and priority in use: epoll + recvmmsg on Linux, NIO / normal priority as the portable fallback
        touchline.app.RuntimeReport runtime = console.runtime();
        platform.setId("status-platform");
        platform.setText(runtime.portability());
        platform.setMinWidth(Region.USE_PREF_SIZE);
        platform.setTooltip(new Tooltip(String.join("\n", runtime.lines())));
        getChildren().addAll(silence, rates, bad, waiting, meterName, meter, meterText, message, grow, platform, fps);
    }

    public double packetsPerSecond() {
        return packetsPerSecond;
    }

    /** A one-line message (layout saved, command held, ...). */
    public void say(String text) {
        message.setText(text);
    }

    /** The frame pulse stopped because nothing changed: the frame rate reads "idle" until it runs again. */
    void idle() {
        fps.setText("idle");
    }

    void refresh(long nowMicros, double framesPerSecond, LatencyProbe latency) {
        if (nowMicros - lastMicros < 500_000) {
            return;
        }
        TransportCounts c = console.transportCounts();
        double dt = lastMicros == 0 ? 1 : (nowMicros - lastMicros) / 1e6;
        packetsPerSecond = (c.datagramsIn() - lastIn) / dt;
        long out = readings.packetsOut();
        rates.setText(String.format("in %.0f pkt/s %s/s · out %.0f pkt/s %s/s", packetsPerSecond,
                bytes((c.bytesIn() - lastBytesIn) / dt), (out - lastOut) / dt,
                bytes((c.bytesOut() - lastBytesOut) / dt)));
        bad.setText("malformed " + c.malformedIn());
        bad.setStyle(c.malformedIn() > 0 ? "-fx-text-fill: #cf222e;" : "");
        int waitingNow = readings.waitingNow();
        waiting.setText(waitingNow == 1 ? "1 request waiting now" : waitingNow + " requests waiting now");
        waitingTip.setText(readings.heldTotal() + " requests held back by match mode since the console started "
                + "(each retry counts); waiting requests go out when play stops");
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
        java.util.Optional<touchline.model.TeamMessageBudget> guard = console.teamMessageBudget();
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
        meterName.setText("Messages");
        meter.setProgress(Math.min(1, f));
        boolean alarm = s.oversize() > 0 || s.verdict() == touchline.model.TeamMessageBudget.Verdict.EXHAUSTED;
        boolean warn = s.verdict() == touchline.model.TeamMessageBudget.Verdict.RUNS_OUT_BEFORE_THE_END;
        meter.setStyle(alarm ? "-fx-accent: #cf222e;" : warn ? "-fx-accent: #bf8700;" : "-fx-accent: #2da44e;");
        java.util.List<touchline.model.DebugRateGuard.OverLimit> over = console.debugRateGuard()
                .map(touchline.model.DebugRateGuard::overLimit).orElse(java.util.List.of());
        alarm |= !over.isEmpty();
        StringBuilder text = new StringBuilder(s.describe());
        over.forEach(o -> text.append(" · ").append(o.describe()).append(" (limit ")
                .append(s.profile().debugPacketsPerSecond().describe()).append(")"));
        meterText.setText(text.toString());
        meterText.setStyle(alarm ? "-fx-text-fill: #cf222e;" : warn ? "-fx-text-fill: #bf8700;" : "");
        StringBuilder tip = new StringBuilder("Team " + s.team() + "'s messages under " + s.profile().name()
                + ": budget " + s.profile().teamMessageBudget().describe() + " per game, at most "
                + s.profile().maxTeamMessageBytes().describe() + " bytes each. Counted in READY, SET and PLAYING.");
        for (touchline.model.TeamMessageBudget.Sender r : s.senders()) {
            tip.append(String.format("%n%s: %d messages, %.0f/min, largest %d bytes%s", r.sender(), r.messages(),
                    r.perMinute(), r.largest(), r.oversize() > 0 ? ", " + r.oversize() + " OVERSIZE" : ""));
        }
        meterTip.setText(tip.toString());
    }

    /** Without a budget guard: the team's traffic against the 1 Mbit/s limit of the leagues before 2026. */
    private void showTraffic() {
        meterName.setText("Team");
        meterTip.setText("Team traffic (IP/UDP included) against the 1 Mbit/s league limit (HL 2025; start with "
                + "--team N for the 2026 team-message budget)");
        TrafficMeter.Reading r = console.traffic().read();
        double f = r.fractionOfLimit();
        meter.setProgress(Math.min(1, f));
        meter.setStyle(f > 1 ? "-fx-accent: #cf222e;" : f > 0.8 ? "-fx-accent: #bf8700;" : "-fx-accent: #2da44e;");
        meterText.setText(String.format("%.0f kbit/s of 1 Mbit/s (%.0f %%)%s", r.teamBitsPerSecond() / 1000, f * 100,
                r.overShare().isEmpty() ? "" : " · over share: " + r.overShare()));
        meterText.setStyle("");
    }

    static String bytes(double b) {
        return b >= 1e6 ? String.format("%.1f MB", b / 1e6) : b >= 1e3 ? String.format("%.1f kB", b / 1e3) : String.format("%.0f B", b);
    }
}
