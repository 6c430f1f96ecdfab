package touchline.app;

import touchline.app.game.MatchMode;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.transport.Envelope;
import touchline.transport.GameStateReader;
import touchline.transport.EnvelopeSink;

/**
 * On a console viewing another Touchline: the GameController packets that console heard (or
 * its embedded GameController sent) come in with the stream and feed this console's match
 * mode, decoded by the same known formats, so its match-mode display shows the remote field's
 * play (a viewer never sends anyway). A packet the remote console did not believe (its error
 * set) changes nothing here either. Then the envelope goes on to {@code next}.
 */
final class RemoteGameState implements EnvelopeSink {

    private final GameStateReader gameStates = new GameStateReader();
    private final MatchMode matchMode;
    private final EnvelopeSink next;

    RemoteGameState(MatchMode matchMode, EnvelopeSink next) {
        this.matchMode = matchMode;
        this.next = next;
    }

    @Override
    public void accept(Envelope e) {
        KnownGameStateFormats.Match m = gameStates.read(e);
        if (m != null) {
            matchMode.observeBelieved(m.data().state(), "the remote console's GameController"
                    + (e.peer() == null ? "" : " at " + e.peer().getHostString() + ":" + e.peer().getPort()));
        }
        next.accept(e);
    }
}
