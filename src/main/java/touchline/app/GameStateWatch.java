package touchline.app;

import touchline.game.MatchMode;
import touchline.proto.Fumanoid;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.gamecontroller.GcProfile;

import java.util.Arrays;
import java.util.List;

/**
 * Feeds match mode with every game state heard on the network: GameController packets of any
 * format in the Envelope stream (from the console's GameController port watch), and the state
 * each robot reports in its keep-alive (what it last heard from the referee). Either says
 * whether a game is on, so the console stays silent even when it cannot hear the referee box
 * itself.
 */
final class GameStateWatch implements EnvelopeSink {

    private static final List<String> STATES = List.of("INITIAL", "READY", "SET", "PLAYING", "FINISHED");

    private final MatchMode matchMode;
    private final List<GameStateFormat> formats = Arrays.stream(GcProfile.values()).map(GcProfile::format).toList();

    GameStateWatch(MatchMode matchMode) {
        this.matchMode = matchMode;
    }

    @Override
    public void accept(Envelope e) {
        if (e.direction() != Direction.IN) {
            return;
        }
        if (e.channel() == Channel.GAMECONTROLLER && e.raw().length >= 4 && e.raw()[2] == 'm' && e.raw()[3] == 'e') {
            for (GameStateFormat f : formats) {
                if (e.raw().length == f.size()) {
                    Decoded<GameControlData> d = f.decode(e.raw());
                    if (d.isOk()) {
                        matchMode.observe(d.value().state(), "GameController at " + describe(e));
                        return;
                    }
                }
            }
            return;
        }
        if (e.message() instanceof Fumanoid.Message m && m.hasExtension(Fumanoid.status)) {
            int state = STATES.indexOf(m.getExtension(Fumanoid.status).getGameState());
            if (state >= 0) {
                matchMode.observe(state, "robot " + e.robotId());
            }
        }
    }

    private static String describe(Envelope e) {
        return e.peer() == null ? "?" : e.peer().getAddress().getHostAddress() + ":" + e.peer().getPort();
    }
}
