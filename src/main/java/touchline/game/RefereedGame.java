package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;

/**
 * What the embedded GameController's sender and receivers need of a refereed game, whatever
 * league's rules it follows ({@link Game} for the Humanoid League, {@code hsl.HslGame} for the
 * 2026 Humanoid Soccer League). In the console one thread owns it ({@code app.game.GameRuntime}):
 * only that thread changes it; the others read the snapshots the owner publishes.
 * Implementations still serialise access, so a test or a tool may read one directly.
 */
public interface RefereedGame {

    /** Called after every change (action, undo, or a change that came with time). */
    void addListener(Runnable onChange);

    long now();

    /** Applies the changes time brings; true when the state (not only a clock) changed. */
    boolean advance();

    /** The packet content robots get now (packetNumber 0). */
    GameControlData controlData();

    /** The true state for monitors; the same as {@link #controlData()} where a league hides nothing. */
    default GameControlData trueData() {
        return controlData();
    }

    /** Whether a team with this number plays in this game. */
    boolean hasTeam(int number);

    /** Performs the action when it is one of this game's league (its own, or one every league shares), else refuses it. */
    Outcome perform(LeagueAction<?> action);

    Outcome undo();

    /** Descriptions of the undoable actions, most recent first. */
    java.util.List<String> undoList();

    /** One line for logs and the CLI's status. */
    String describe();
}
