package touchline.ui.referee;

import javafx.scene.control.Button;
import touchline.game.LeagueAction;
import touchline.game.hsl.HslState;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

/**
 * The referee box's buttons and the actions they dispatch: each press only enqueues through the
 * {@link HslRefereeModel} and redraws the box at once (a chosen call, the outcomes that came);
 * each frame takes the owner's answers and enables exactly the buttons whose action the rules
 * allow now.
 */
final class RefereeButtons {

    /** A button and the action it dispatches, enabled when that action is legal. */
    private record Bound(Button button, Supplier<LeagueAction<? super HslState>> action) {
    }

    private final HslRefereeModel model;
    private final Runnable show;
    private final List<Bound> bound = new ArrayList<>();

    /** @param show redraws the box after an action */
    RefereeButtons(HslRefereeModel model, Runnable show) {
        this.model = model;
        this.show = show;
    }

    /** Does what the referee asked (enqueues an action, or chooses a call) and redraws the box. */
    void act(Runnable referee) {
        referee.run();
        show.run();
    }

    /** A button that performs {@code action} (built when pressed, for the team on that side then). */
    Button button(String id, String text, Supplier<LeagueAction<? super HslState>> action) {
        Button b = new Button(text);
        b.setId(id);
        b.setOnAction(e -> act(() -> model.perform(action.get())));
        bound.add(new Bound(b, action));
        return b;
    }

    /** A button that does something of its own but is enabled when {@code legalWhen} is legal. */
    Button button(String id, String text, Supplier<LeagueAction<? super HslState>> legalWhen, Runnable press) {
        Button b = button(id, text, legalWhen);
        b.setOnAction(e -> act(press));
        return b;
    }

    void refresh() {
        for (Bound b : bound) {
            b.button().setDisable(!model.legal(b.action().get()));
        }
    }
}
