package touchline.ui.referee;

import touchline.game.hsl.AddAdditionalTime;
import touchline.game.hsl.FinishHalf;
import touchline.game.hsl.FinishSetPlay;
import touchline.game.hsl.FreeSetPlay;
import touchline.game.hsl.GlobalGameStuck;
import touchline.game.Goal;
import touchline.game.LeagueAction;
import touchline.app.game.GameRuntime;
import touchline.game.hsl.HslPlayState;
import touchline.game.hsl.HslPlayer;
import touchline.game.hsl.HslState;
import touchline.game.hsl.HslTeam;
import touchline.game.hsl.HslPenalize;
import touchline.game.hsl.SetPlay;
import touchline.game.hsl.HslStartSetPlay;
import touchline.game.hsl.StopPlay;
import touchline.game.hsl.SwitchHalf;
import touchline.game.hsl.HslTimeout;
import touchline.game.hsl.HslUnpenalize;
import touchline.game.hsl.WaitForSetPlay;
import touchline.protocol.gamecontroller.HslPenalty;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * What the HSL referee box shows and does, without a window: per frame a snapshot of the
 * HSL game its {@link GameRuntime} owns; for every button the action it dispatches and whether the rules allow it
 * now (the action's own {@code isLegal}); the texts of the clocks, teams and robots; the
 * penalty the referee has chosen and is about to give to a robot (as in the official
 * GameController, the call first, then the robot); and the outcome of the last action, which
 * says why an illegal one was refused. An action only enqueues: its outcome is taken at the
 * frame after the owner answered ({@code RefereeOutcomes}), so the JavaFX thread never waits.
 * The view only binds to it.
 */
public final class HslRefereeModel {

    private final GameRuntime game;
    private HslState state;
    private final RefereeOutcomes outcomes;
    private HslPenalty chosen;

    /** @param game the owner of an HSL game: actions are enqueued to it, frames read its snapshot */
    public HslRefereeModel(GameRuntime game) {
        this.game = game;
        this.outcomes = new RefereeOutcomes(game::now);
        this.state = game.snapshot().hslAt(game.now());
    }

    /** The game's clock. */
    public long now() {
        return game.now();
    }

    /**
     * Takes the outcomes that came and this frame's snapshot of the game (time run on to now, on a
     * copy); everything else reads it.
     */
    public void refresh() {
        outcomes.pull(); // first: the snapshot is published before an outcome comes
        state = game.snapshot().hslAt(game.now());
        if (chosen != null && !penaltyLegal(chosen)) {
            chosen = null;
        }
    }

    public HslState state() {
        return state;
    }

    // ---- actions -------------------------------------------------------------------------

    /** Whether the rules allow {@code action} now (on this frame's snapshot). */
    public boolean legal(LeagueAction<? super HslState> action) {
        return action.isLegal(state);
    }

    /**
     * Enqueues {@code action} to the game; its outcome (or why it was refused) is {@link #message()}
     * from the first {@link #refresh()} after the owner answered.
     */
    public void perform(LeagueAction<? super HslState> action) {
        outcomes.expect(game.perform(action));
    }

    /** Enqueues an undo of the last action, as {@link #perform}. */
    public void undo() {
        outcomes.expect(game.undo());
    }

    /** The last outcome: what was done, or why it was refused. */
    public String message() {
        return outcomes.message();
    }

    public boolean refused() {
        return outcomes.refused();
    }

    /** Whether an action enqueued has not been answered yet (as of the last {@link #refresh()}). */
    public boolean waiting() {
        return outcomes.waiting();
    }

    public int teamNumber(int side) {
        return state.teamOnSide(side).number();
    }

    /** Stop play, or resume it when stopped (the big button, Space). */
    public LeagueAction<? super HslState> stopOrResume() {
        return new StopPlay(state.stopped());
    }

    public String stopOrResumeLabel() {
        return state.stopped() ? "Resume (Space)" : "Stop (Space)";
    }

    /**
     * The kick-off due now: READY for the team whose kick-off it is (the official "Ready"),
     * or, when no team kicks off, the left team's (then refused with the reason).
     */
    public LeagueAction<? super HslState> ready() {
        int kicking = state.kickingTeam();
        return new HslStartSetPlay(kicking == HslState.NO_TEAM ? teamNumber(0) : kicking, SetPlay.KICK_OFF);
    }

    public LeagueAction<? super HslState> set() {
        return new WaitForSetPlay();
    }

    public LeagueAction<? super HslState> play() {
        return new FreeSetPlay();
    }

    public LeagueAction<? super HslState> ballFree() {
        return new FinishSetPlay();
    }

    public LeagueAction<? super HslState> droppedBall() {
        return new GlobalGameStuck();
    }

    public LeagueAction<? super HslState> additionalMinute() {
        return new AddAdditionalTime();
    }

    public LeagueAction<? super HslState> finishHalf() {
        return new FinishHalf();
    }

    public LeagueAction<? super HslState> secondHalf() {
        return new SwitchHalf();
    }

    public LeagueAction<? super HslState> refereeTimeout() {
        return new HslTimeout(HslTimeout.REFEREE);
    }

    public LeagueAction<? super HslState> setPlay(int side, SetPlay kind) {
        return new HslStartSetPlay(teamNumber(side), kind);
    }

    public LeagueAction<? super HslState> goal(int side) {
        return new Goal(teamNumber(side));
    }

    public LeagueAction<? super HslState> timeout(int side) {
        return new HslTimeout(teamNumber(side));
    }

    // ---- penalties: the call first, then the robot ----------------------------------------

    /** The calls of this release, in the official GameController's order (no substitute). */
    public List<HslPenalty> calls() {
        List<HslPenalty> out = new ArrayList<>();
        for (HslPenalty p : HslPenalty.values()) {
            if (p != HslPenalty.NONE && p != HslPenalty.SUBSTITUTE && state.rules().knows(p)
                    && ((p != HslPenalty.CAUTIONED && p != HslPenalty.SENT_OFF) || state.rules().cautions())) {
                out.add(p);
            }
        }
        return out;
    }

    /** Chooses the call the next robot press gives; choosing it again (or null) cancels it. */
    public void choose(HslPenalty call) {
        chosen = call == null || call == chosen ? null : call;
        if (chosen != null && !penaltyLegal(chosen)) {
            outcomes.say("no robot can get " + label(chosen) + " now (" + state.describe() + ")", true);
            chosen = null;
        } else {
            outcomes.say(chosen == null ? "" : label(chosen) + ": now press the robot", false);
        }
    }

    public HslPenalty chosen() {
        return chosen;
    }

    /** Whether some robot on the field could get {@code call} now. */
    public boolean penaltyLegal(HslPenalty call) {
        for (int side = 0; side < 2; side++) {
            for (int n = 1; n <= playersPerTeam(); n++) {
                if (legal(new HslPenalize(teamNumber(side), n, call))) {
                    return true;
                }
            }
        }
        return false;
    }

    public int playersPerTeam() {
        return state.rules().competition().playersPerTeam();
    }

    /**
     * What pressing robot {@code player} on {@code side} does: with a call chosen, that
     * penalty; else on a penalised robot the official unpenalise button (start the timer, or
     * let it back in once the timer ran out).
     */
    public LeagueAction<? super HslState> robotAction(int side, int player) {
        int team = teamNumber(side);
        return chosen != null ? new HslPenalize(team, player, chosen) : new HslUnpenalize(team, player, false);
    }

    /**
     * Enqueues what pressing the robot does ({@link #robotAction}). A call is used once: it is
     * given back when its outcome says the robot could not get it (and no other was chosen since).
     */
    public void pressRobot(int side, int player) {
        LeagueAction<? super HslState> action = robotAction(side, player);
        HslPenalty call = chosen;
        chosen = null;
        outcomes.expect(game.perform(action), o -> {
            if (!o.applied() && chosen == null) {
                chosen = call;
            }
        });
    }

    /** The robot button's text; the same width whatever it says, so the row never moves. */
    public String robotButtonText(int side, int player) {
        HslPlayer p = state.teamOnSide(side).player(player);
        if (chosen != null) {
            return "Penalise";
        }
        if (!p.isPenalised()) {
            return "Playing";
        }
        if (p.penalty() == HslPenalty.SENT_OFF || p.penalty() == HslPenalty.SUBSTITUTE) {
            return "Out";
        }
        if (!p.timerStarted()) {
            return "Start timer";
        }
        return p.secsTillUnpenalised() > 0 ? "Running" : "Back in";
    }

    /** Jersey, goalkeeper mark, penalty with its seconds, cautions, and liveness. */
    public String robotText(int side, int player, String liveness) {
        HslPlayer p = state.teamOnSide(side).player(player);
        boolean keeper = state.teamOnSide(side).goalkeeper() == player;
        String penalty;
        if (!p.isPenalised()) {
            penalty = "";
        } else if (p.timerStarted() || p.penalty() == HslPenalty.MOTION_IN_SET) {
            penalty = String.format("%s %3d s", shortLabel(p.penalty()), p.secsTillUnpenalised());
        } else {
            penalty = shortLabel(p.penalty()) + (p.penalty() == HslPenalty.SENT_OFF ? "" : " wait");
        }
        String cautions = p.cautions() > 0 ? "C".repeat(p.cautions()) : "";
        return String.format("%2d %-2s %-18s %-2s %-7s", player, keeper ? "GK" : "", penalty, cautions, liveness);
    }

    public static String label(HslPenalty call) {
        return switch (call) {
            case PLAYING_WITH_ARMS_HANDS -> "arms/hands";
            case CAUTIONED -> "caution";
            case SENT_OFF -> "sent off";
            default -> call.name().toLowerCase(Locale.ROOT).replace('_', ' ');
        };
    }

    /** At most 16 characters, for the call buttons. */
    public static String buttonLabel(HslPenalty call) {
        return switch (call) {
            case ILLEGAL_POSITIONING -> "illegal position";
            case LEAVING_THE_FIELD -> "leaving field";
            default -> label(call);
        };
    }

    /** At most 12 characters, for the robot rows. */
    static String shortLabel(HslPenalty call) {
        return switch (call) {
            case ILLEGAL_POSITIONING -> "illegal pos";
            case MOTION_IN_SET -> "motion set";
            case MOTION_IN_STOP -> "motion stop";
            case LOCAL_GAME_STUCK -> "game stuck";
            case INCAPABLE_ROBOT -> "incapable";
            case LEAVING_THE_FIELD -> "left field";
            case BALL_HOLDING -> "ball holding";
            default -> label(call);
        };
    }

    // ---- texts ---------------------------------------------------------------------------

    /** Whole seconds as {@code "  9:58"} or {@code " -0:05"}: always six characters. */
    static String clock(int seconds) {
        int a = Math.abs(seconds);
        return String.format("%6s", (seconds < 0 ? "-" : "") + a / 60 + ":" + String.format("%02d", a % 60));
    }

    public String mainClock() {
        return clock(state.secsRemaining());
    }

    /** The secondary clock with what it counts, or blanks of the same width. */
    public String secondaryClock() {
        int secs = state.secondaryTime();
        return secs == 0 && state.setPlay() == null && state.state() != HslPlayState.TIMEOUT ? "      " : clock(secs);
    }

    /** e.g. {@code PLAYING · stopped · corner kick 14 · 1st half}. */
    public String stateText() {
        StringBuilder b = new StringBuilder(state.state().name());
        if (state.phase() != touchline.game.hsl.HslPhase.NORMAL) {
            b.append(' ').append(state.phase().name().toLowerCase(Locale.ROOT).replace('_', ' '));
        }
        if (state.stopped()) {
            b.append(" · STOPPED");
        }
        if (state.setPlay() != null) {
            b.append(" · ").append(state.setPlay().label());
            if (state.kickingTeam() != HslState.NO_TEAM) {
                b.append(' ').append(state.kickingTeam());
            } else {
                b.append(" (dropped ball)");
            }
        }
        b.append(state.firstHalf() ? " · 1st half" : " · 2nd half");
        if (state.delaying()) {
            b.append(" · robots still see SET");
        }
        return b.toString();
    }

    public String teamTitle(int side) {
        HslTeam t = state.teamOnSide(side);
        return "Team " + t.number() + (side == 0 ? " (left)" : " (right)");
    }

    public String colours(int side) {
        HslTeam t = state.teamOnSide(side);
        return name(t.fieldColour().name()) + ", goalkeeper " + name(t.goalkeeperColour().name());
    }

    private static String name(String constant) {
        return constant.toLowerCase(Locale.ROOT);
    }

    public String score(int side) {
        return Integer.toString(state.teamOnSide(side).score());
    }

    /** The team's message budget from the game state, and illegal communication when it happened. */
    public String budget(int side) {
        HslTeam t = state.teamOnSide(side);
        return String.format("Messages left %5d%s", t.messageBudget(),
                t.illegalCommunication() ? " · ILLEGAL COMMUNICATION: score 0" : "");
    }

    public String timeoutsLeft(int side) {
        return "Timeouts left " + state.teamOnSide(side).timeoutsLeft();
    }
}
