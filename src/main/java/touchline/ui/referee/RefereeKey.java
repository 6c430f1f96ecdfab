package touchline.ui.referee;

import javafx.scene.input.KeyCode;
import touchline.game.LeagueAction;
import touchline.game.hsl.HslState;

import java.util.Arrays;
import java.util.Optional;
import java.util.function.Function;

/**
 * The referee's single keys in the HSL GameController tab: what the tab does on each, and the
 * words the help (F1) and the shortcut sheet (Ctrl+/) show for it, from this one list so the
 * two cannot drift apart.
 */
public enum RefereeKey {
    STOP_OR_RESUME(KeyCode.SPACE, "Space", "stop or resume play", HslRefereeModel::stopOrResume),
    READY(KeyCode.R, "R", "Ready (the kick-off team's countdown)", HslRefereeModel::ready),
    SET(KeyCode.S, "S", "Set", HslRefereeModel::set),
    PLAY(KeyCode.P, "P", "Play", HslRefereeModel::play),
    BALL_FREE(KeyCode.B, "B", "ball free (ends a set play's wait)", HslRefereeModel::ballFree),
    DROPPED_BALL(KeyCode.D, "D", "dropped ball", HslRefereeModel::droppedBall),
    ADDITIONAL_MINUTE(KeyCode.A, "A", "+1 minute of play", HslRefereeModel::additionalMinute),
    FORGET_CALL(KeyCode.ESCAPE, "Esc", "forget the call chosen before its robot was picked", m -> null);

    private final KeyCode code;
    private final String keys;
    private final String what;
    private final Function<HslRefereeModel, LeagueAction<? super HslState>> action;

    RefereeKey(KeyCode code, String keys, String what, Function<HslRefereeModel, LeagueAction<? super HslState>> action) {
        this.code = code;
        this.keys = keys;
        this.what = what;
        this.action = action;
    }

    /** The key as the help writes it ("Space", "R", "Esc"). */
    public String keys() {
        return keys;
    }

    /** What it does, in the referee's words. */
    public String what() {
        return what;
    }

    /** The action the key asks of the game now (null for {@link #FORGET_CALL}, which acts on the tab). */
    LeagueAction<? super HslState> action(HslRefereeModel model) {
        return action.apply(model);
    }

    static Optional<RefereeKey> of(KeyCode code) {
        return Arrays.stream(values()).filter(k -> k.code == code).findFirst();
    }
}
