package touchline.app;

import touchline.app.game.MatchMode;
import touchline.transport.SendGate;

import java.util.Optional;

/**
 * What may go to robots right now (GameController packets aside): held by match mode during
 * play, shut for good with {@link RemoteView#COMMANDS_OFF} once the console views a remote
 * Touchline. One gate for the UDP transport, the reliable streams and the NAO calls.
 */
final class FieldGate {

    /** What the match-mode gate adds for debug requests, which are asked again after play; a NAO call is not. */
    private static final String SENT_LATER = "; goes out when play stops";

    private final LiveField field;
    private volatile SendGate gate = SendGate.open();
    private volatile boolean commandsOff;

    FieldGate(LiveField field, MatchMode matchMode) {
        this.field = field;
        set(() -> matchMode.hold("console request")
                ? Optional.of("match mode, " + matchMode.play() + SENT_LATER) : Optional.empty());
    }

    private void set(SendGate gate) {
        this.gate = gate;
        field.udp().setGate(gate);
        field.reliable().setGate(gate);
    }

    /** Viewing a remote Touchline: nothing goes to robots from now on. */
    void shut() {
        commandsOff = true;
        set(() -> Optional.of(RemoteView.COMMANDS_OFF));
    }

    /** True once the console views a remote Touchline. */
    boolean commandsOff() {
        return commandsOff;
    }

    /** The gate for NAO calls: held NAO commands are dropped, never sent when play stops, and say so. */
    SendGate forNao() {
        return () -> gate.holdReason().map(r -> r.endsWith(SENT_LATER)
                ? r.substring(0, r.length() - SENT_LATER.length()) + "; not sent" : r);
    }
}
