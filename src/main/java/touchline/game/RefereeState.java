package touchline.game;

/**
 * What every league's state answers to the actions the leagues share ({@link RefereeAction}s such
 * as {@link Goal}): the rule is the action's, what it means in a league's state (its clocks, its
 * set plays, its shoot-out) is the state's. {@link GameState} (HL, SPL) and {@code hsl.HslState}
 * implement it. The changes are meant for the actions; a face only ever holds a snapshot.
 */
public interface RefereeState {

    /** Whether the ball is in play (PLAYING). */
    boolean playing();

    boolean inShootout();

    /** Team number of the team that kicks now (in a shoot-out the shooter's). */
    int kickingTeam();

    /** What the shared actions read of a team ({@link TeamState}, {@code hsl.HslTeam}). */
    interface Team {
        int number();

        int score();
    }

    /** The team on side 0 (left) or 1 (right). */
    Team teamOnSide(int side);

    default boolean hasTeam(int number) {
        return teamOnSide(0).number() == number || teamOnSide(1).number() == number;
    }

    /** Team number of the other team. */
    default int opponent(int number) {
        return teamOnSide(teamOnSide(0).number() == number ? 1 : 0).number();
    }

    /** FINISHED (a half, a shot or the game). */
    boolean finished();

    boolean firstHalf();

    /** Team number of the team that kicked off the game. */
    int gameKickOffTeam();

    /** The goal difference that ends the game at once (the mercy rule), 0 for none. */
    int mercyGoals();

    /** Goals between the two teams' scores. */
    default int goalDifference() {
        return Math.abs(teamOnSide(0).score() - teamOnSide(1).score());
    }

    /** +1 for the team, unless the league voids its goals (HSL: marked for illegal communication). */
    void countGoal(int team);

    /** The team's shoot-out shot scored: its bit in singleShots, and the shot is over. */
    void shotScored(int team, long nowMs);

    /** The game is over (no half-time, no second half). */
    void endGame(long nowMs);

    /** The penalty shoot-out begins with {@code first} to shoot: INITIAL, both teams' shot counters 0. */
    void beginShootout(int first, long nowMs);

    /** Play stopped for a kick-off of {@code team}: READY. */
    void readyForKickOff(int team, long nowMs);
}
