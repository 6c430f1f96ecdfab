package touchline.transport.gamecontroller;

import touchline.app.game.GameRuntime;
import touchline.game.Outcome;
import touchline.game.hsl.HslActionSyntax;

import static org.junit.jupiter.api.Assertions.assertTrue;

/** A golden script's command given to a running GameController's owner, as the referee box would. */
final class RefereeScript {

    private RefereeScript() {
    }

    static void perform(GameRuntime owner, String command, String where) {
        HslActionSyntax.Parsed parsed = new HslActionSyntax().parse(command);
        assertTrue(parsed.error() == null, where + ": '" + command + "': " + parsed.error());
        Outcome o = GameRuntime.outcome(owner.perform(parsed.action()));
        assertTrue(o.applied(), where + ": '" + command + "' refused: " + o.message());
    }
}
