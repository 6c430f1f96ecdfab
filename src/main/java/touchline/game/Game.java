package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;

import java.util.List;

/**
 * One refereed game under the Humanoid League (or SPL) rules: the one {@link RefereeEngine} with
 * the {@link HlLeague}'s way of running time, over a {@link GameState}.
 * In the console its one owner is {@code app.game.GameRuntime}, which calls every method on its
 * thread; access is serialised all the same. Listeners hear about every change (action, undo, or
 * a change that happened by itself in {@link #advance()}) on the thread that made it.
 */
public final class Game implements RefereedGame {

    /** How many actions can be undone. */
    public static final int UNDO_DEPTH = RefereeEngine.UNDO_DEPTH;

    private final RefereeEngine<GameState> engine;

    /**
     * @param params  league rules
     * @param teamA   team number on the left side in the first half (kicks off first)
     * @param colourA its colour (0 blue, 1 red, ...)
     * @param teamB   team number on the right side
     * @param colourB its colour
     * @param clock   the time source
     */
    public Game(LeagueParams params, int teamA, int colourA, int teamB, int colourB, GameClock clock) {
        if (teamA == teamB) {
            throw new IllegalArgumentException("the two teams need different numbers");
        }
        this.engine = new RefereeEngine<>(new HlLeague(),
                new GameState(params, teamA, colourA, teamB, colourB, clock.millis()), clock);
    }

    @Override
    public void addListener(Runnable onChange) {
        engine.addListener(onChange);
    }

    @Override
    public long now() {
        return engine.now();
    }

    /**
     * Lets time-driven changes happen (then checks legality), applies the action, notifies; an
     * {@link Action} or one every league shares, else refused.
     */
    @Override
    public Outcome perform(LeagueAction<?> action) {
        LeagueAction<? super GameState> own = RefereeAction.of(action, Action.class);
        return own == null ? RefereeAction.refused(action) : engine.perform(own);
    }

    /** Applies changes that happen as time passes (penalties ending, half-time switch). */
    @Override
    public boolean advance() {
        return engine.advance();
    }

    /** Reverts the last applied action (timers keep running as if it had never happened). */
    @Override
    public Outcome undo() {
        return engine.undo();
    }

    /** Descriptions of the undoable actions, most recent first. */
    @Override
    public List<String> undoList() {
        return engine.undoList();
    }

    public boolean isLegal(LeagueAction<?> action) {
        LeagueAction<? super GameState> own = RefereeAction.of(action, Action.class);
        return own != null && engine.read((s, now) -> own.isLegal(s));
    }

    @Override
    public boolean hasTeam(int number) {
        return engine.read((s, now) -> s.team(number) != null);
    }

    /** A copy of the current state, safe to read on any thread. */
    public GameState snapshot() {
        return engine.read((s, now) -> s.copy());
    }

    /** The packet content right now (packetNumber 0). */
    @Override
    public GameControlData controlData() {
        return engine.read(GameState::toControlData);
    }

    /** One line such as {@code PLAYING 1st half, 512 s, kick-off 7, 1:0}. */
    @Override
    public String describe() {
        return engine.read(GameState::describe);
    }
}
