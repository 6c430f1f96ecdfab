package touchline.app;

import touchline.app.game.MatchMode;
import touchline.proto.Fumanoid;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;


/**
 * Feeds match mode with the game state each robot reports in its keep-alive (what it last
 * heard from the referee's GameController), so the console stays silent during play even when
 * it cannot hear the GameController itself (the port watch covers the case where it can).
 * Subscribed to the live stream only: replayed robots are not on the field, and what they
 * reported never changes match mode.
 */
final class ReportedGameState implements EnvelopeSink {

    private final MatchMode matchMode;

    ReportedGameState(MatchMode matchMode) {
        this.matchMode = matchMode;
    }

    @Override
    public void accept(Envelope e) {
        Fumanoid.Status status = e.direction() == Direction.IN ? e.extension(Fumanoid.status) : null;
        if (status != null) {
            int state = GameControlData.stateCode(status.getGameState());
            // the five states every league's robots report; SPL's STANDBY never reached match mode
            if (state >= 0 && state <= GameControlData.STATE_FINISHED) {
                matchMode.observeReported(state, e.robotId());
            }
        }
    }
}
