package touchline.app.game;

import touchline.game.Game;
import touchline.game.GameState;
import touchline.game.RefereedGame;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslState;
import touchline.protocol.gamecontroller.GameControlData;

import java.util.List;

/**
 * The refereed game as it was after one event of its {@link GameRuntime}: what robots get, the
 * true state for monitors, a line for people, and a private copy of the league's state for the
 * views. Nobody changes it after the owner published it: a reader who needs time run on takes
 * {@link #hslAt(long)}, which is a copy of its own.
 *
 * @param robots      the packet content robots get (packetNumber 0)
 * @param truth       the true state for monitors (the same as {@code robots} where a league hides nothing)
 * @param description one line such as {@code PLAYING 1st half, 512 s left, ...}
 * @param hl          the HL/SPL state, or null in an HSL game
 * @param hsl         the HSL state, or null in an HL/SPL game
 * @param undoList    the undoable actions, most recent first
 */
public record RefereeSnapshot(GameControlData robots, GameControlData truth, String description, GameState hl,
                              HslState hsl, List<String> undoList) {

    /** Takes the snapshot; on the game's owner thread only. */
    static RefereeSnapshot of(RefereedGame game) {
        GameControlData robots = game.controlData();
        if (game instanceof HslGame h) {
            return new RefereeSnapshot(robots, h.trueData(), h.describe(), null, h.snapshot(), h.undoList());
        }
        Game g = (Game) game;
        return new RefereeSnapshot(robots, robots, g.describe(), g.snapshot(), null, g.undoList());
    }

    /**
     * This snapshot as the owner's timer event would leave the game at {@code nowMs}, computed
     * by the league's own rules on private copies: what a periodic send sends at its instant
     * without waiting for the owner ({@link GameRuntime#timed()}). This snapshot stays as it is.
     */
    public RefereeSnapshot at(long nowMs) {
        if (hsl != null) {
            HslState h = hsl.at(nowMs);
            return new RefereeSnapshot(h.robotData(), h.trueData(), h.describe(), null, h, undoList);
        }
        GameState g = hl.at(nowMs);
        GameControlData data = g.toControlData(nowMs);
        return new RefereeSnapshot(data, data, g.describe(nowMs), g, null, undoList);
    }

    /** Whether a team with this number plays in this game. */
    public boolean hasTeam(int number) {
        return truth.team(number) != null;
    }

    /** The HSL state with time run on to {@code nowMs}: a copy of its own (never this snapshot's). */
    public HslState hslAt(long nowMs) {
        return hsl.at(nowMs);
    }
}
