package touchline.app;

import touchline.app.game.MatchMode;
import touchline.transport.Hold;
import touchline.transport.SendGate;

import java.util.Optional;

/**
 * What may go to robots right now (GameController packets aside): held by match mode during
 * play, shut for good with {@link RemoteView#COMMANDS_OFF} once the console views a remote
 * Touchline. One gate for the UDP transport, the reliable streams and the NAO calls.
 */
final class FieldGate {

    private final LiveField field;
    private volatile SendGate gate = SendGate.open();
    private volatile boolean commandsOff;

    FieldGate(LiveField field, MatchMode matchMode) {
        this.field = field;
        set(() -> matchMode.hold("console request")
                ? Optional.of(Hold.untilPlayStops("match mode, " + matchMode.play())) : Optional.empty());
    }

    private void set(SendGate gate) {
        this.gate = gate;
        field.udp().setGate(gate);
        field.reliable().setGate(gate);
    }

    /** Viewing a remote Touchline: nothing goes to robots from now on. */
    void shut() {
        commandsOff = true;
        set(() -> Optional.of(Hold.always(RemoteView.COMMANDS_OFF)));
    }

    /** True once the console views a remote Touchline. */
    boolean commandsOff() {
        return commandsOff;
    }

    /** The gate for ROS 2 bridges' commands: held ones go out when play stops ({@link Hold#queued()}), refused when shut. */
    SendGate forBridges() {
        return () -> gate.hold();
    }

    /** The gate for NAO calls: held NAO commands are dropped, never sent when play stops (NaoLink says so: {@link Hold#dropped()}). */
    SendGate forNao() {
        return () -> gate.hold();
    }
}
