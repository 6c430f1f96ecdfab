package touchline.game;

import java.util.List;
import java.util.function.BiFunction;

/**
 * One refereed game of a league: the one {@link RefereeEngine} with the league's {@link League}
 * over its state, taking the league's own actions and those every league shares ({@link
 * RefereeAction}), refusing another league's. {@link Game} (HL, SPL) and {@code hsl.HslGame} add
 * how they are built and what they send. In the console its one owner is {@code
 * app.game.GameRuntime}; access is serialised all the same; listeners hear about every change.
 *
 * @param <S> the league's state
 */
public abstract class LeagueGame<S extends RefereeState> implements RefereedGame {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = RefereeEngine.UNDO_DEPTH;

    private final RefereeEngine<S> engine;
    private final Class<? extends LeagueAction<S>> ownActions;

    /**
     * @param league     how time and an action land
     * @param initial    the state at the start
     * @param clock      the time source
     * @param ownActions the league's own action type ({@link Action}, {@code hsl.HslAction})
     */
    protected LeagueGame(League<S> league, S initial, GameClock clock, Class<? extends LeagueAction<S>> ownActions) {
        this.engine = new RefereeEngine<>(league, initial, clock);
        this.ownActions = ownActions;
    }

    @Override
    public final void addListener(Runnable onChange) {
        engine.addListener(onChange);
    }

    @Override
    public final long now() {
        return engine.now();
    }

    /**
     * Lets time pass, checks legality, applies the action, notifies: one of the league's own or
     * one every league shares, else refused.
     */
    @Override
    public final Outcome perform(LeagueAction<?> action) {
        LeagueAction<? super S> own = RefereeAction.of(action, ownActions);
        return own == null ? RefereeAction.refused(action) : engine.perform(own);
    }

    public final boolean isLegal(LeagueAction<?> action) {
        LeagueAction<? super S> own = RefereeAction.of(action, ownActions);
        return own != null && read((s, now) -> own.isLegal(s));
    }

    /** Applies the changes time brings (penalties ending, halves switching, timers running out). */
    @Override
    public final boolean advance() {
        return engine.advance();
    }

    /** Reverts the last applied action. */
    @Override
    public final Outcome undo() {
        return engine.undo();
    }

    @Override
    public final List<String> undoList() {
        return engine.undoList();
    }

    @Override
    public final boolean hasTeam(int number) {
        return engine.read((s, now) -> s.hasTeam(number));
    }

    /** Reads the state at the clock's now; a league whose readers must see time run on first says so here. */
    protected <R> R read(BiFunction<S, Long, R> read) {
        return engine.read(read);
    }
}
