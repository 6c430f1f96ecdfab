package touchline.ui.frame;

import touchline.app.LiveField;
import touchline.app.Referee;
import touchline.app.RemoteView;
import touchline.app.Replays;
import touchline.app.Replay;
import touchline.model.OptionState;
import touchline.model.RobotSnapshot;
import touchline.app.TransportCounts;
import touchline.app.game.EmbeddedGameController;

import java.util.Optional;

/**
 * What the status bar says, read from the console without JavaFX: why the console is silent
 * (match mode, a replay, live traffic paused), how many requests wait right now, and the
 * packets that went out, the embedded GameController's included.
 */
public final class ConsoleStatus {

    private final LiveField field;
    private final Referee referee;
    private final Replays replays;
    private final RemoteView remote;
    private EmbeddedGameController countedSender;
    private long earlierSendersPackets;

    public ConsoleStatus(LiveField field, Referee referee, Replays replays, RemoteView remote) {
        this.field = field;
        this.referee = referee;
        this.replays = replays;
        this.remote = remote;
    }

    /** Why the console does not send or does not listen, in words; "" when it does both. */
    public String silence() {
        StringBuilder s = new StringBuilder();
        remote.status().ifPresent(r -> s.append(r.describe()).append("; ")
                .append(touchline.app.Console.COMMANDS_OFF));
        String play = referee.matchMode().play();
        if (!play.isEmpty()) {
            append(s, referee.matchMode().isOverridden()
                    ? "MATCH MODE OVERRIDDEN: " + play + ", the console sends anyway"
                    : "Silent: match mode, " + play);
        }
        String gc = referee.sources().warning();
        if (!gc.isEmpty()) {
            append(s, gc);
        }
        Optional<Replay> replay = replays.current();
        if (replay.isPresent()) {
            append(s, "Replay: views show the recording" + (replay.get().state().playing() ? " (playing)" : " (paused)")
                    + "; nothing is sent for replayed robots");
        }
        if (!field.liveListening()) {
            append(s, "Live traffic paused: robots on the field are not shown");
        }
        return s.toString();
    }

    private static void append(StringBuilder s, String part) {
        if (!s.isEmpty()) {
            s.append(" · ");
        }
        s.append(part);
    }

    /**
     * Debug-option changes not in effect while match mode holds the console back: they go out
     * when play stops. 0 while the console may send (they are on their way).
     */
    public int waitingNow() {
        if (referee.matchMode().mayConsoleSend()) {
            return 0;
        }
        int waiting = 0;
        for (RobotSnapshot r : field.robots().robots()) {
            for (OptionState o : field.options().options(r.id()).options()) {
                if (o.wanted() != o.enabledOnRobot()) {
                    waiting++;
                }
            }
        }
        return waiting;
    }

    /** Every request match mode held back since the console started, retries included. */
    public long heldTotal() {
        return referee.matchMode().heldCount();
    }

    /** Datagrams sent so far: robots (UDP transport) and GameController packets; never goes down. */
    public long packetsOut() {
        TransportCounts c = field.transportCounts();
        EmbeddedGameController sender = referee.gameController().orElse(null);
        if (sender != countedSender) {
            if (countedSender != null) {
                earlierSendersPackets += countedSender.packetsSent();
            }
            countedSender = sender;
        }
        return c.datagramsOut() + earlierSendersPackets + (sender == null ? 0 : sender.packetsSent());
    }
}
