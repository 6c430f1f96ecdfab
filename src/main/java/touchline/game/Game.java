package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;

/**
 * One refereed game under the Humanoid League (or SPL) rules: a {@link LeagueGame} with the
 * {@link HlLeague}'s way of running time, over a {@link GameState}, taking {@link Action}s and the
 * actions every league shares. An undo reverts the last action (timers keep running as if it had
 * never happened).
 */
public final class Game extends LeagueGame<GameState> {

    /**
     * @param params  league rules
     * @param teamA   team number on the left side in the first half (kicks off first)
     * @param colourA its colour (0 blue, 1 red, ...)
     * @param teamB   team number on the right side
     * @param colourB its colour
     * @param clock   the time source
     */
    public Game(LeagueParams params, int teamA, int colourA, int teamB, int colourB, GameClock clock) {
        super(new HlLeague(), new GameState(params, teamA, colourA, teamB, colourB, clock.millis()), clock,
                Action.class);
    }

    /** A copy of the current state, safe to read on any thread. */
    public GameState snapshot() {
        return read((s, now) -> s.copy());
    }

    /** The packet content right now (packetNumber 0). */
    @Override
    public GameControlData controlData() {
        return read(GameState::toControlData);
    }

    /** One line such as {@code PLAYING 1st half, 512 s, kick-off 7, 1:0}. */
    @Override
    public String describe() {
        return read(GameState::describe);
    }
}
