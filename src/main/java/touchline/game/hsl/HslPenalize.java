package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslPenalty;

import java.util.Locale;

/**
 * Calls a penalty on a player. A removal penalty waits for the operator to start its timer
 * ({@link HslUnpenalize}); motion in set (in SET only) starts at once and ends by itself; motion
 * in stop can only be called while play is stopped; pick-up (also in FINISHED) has no time
 * in INITIAL, a timeout or FINISHED. A caution (7.x) is a removal penalty that counts, and a second caution sends the
 * player off; cautions and send-offs can be given to penalised players.
 */
public record HslPenalize(int team, int player, HslPenalty call) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        HslTeam t = s.team(team);
        if (t == null || !HslTeam.validPlayer(player) || !s.rules.knows(call) || call == HslPenalty.NONE
                || call == HslPenalty.SUBSTITUTE || (s.state == HslPlayState.FINISHED && call != HslPenalty.PICK_UP)) {
            return false;
        }
        if ((call == HslPenalty.CAUTIONED || call == HslPenalty.SENT_OFF) && !s.rules.cautions()) {
            return false;
        }
        HslPlayer p = t.player(player);
        boolean free = !p.isPenalised()
                || ((call == HslPenalty.CAUTIONED || call == HslPenalty.SENT_OFF) && !p.permanent());
        return free && switch (call) {
            case MOTION_IN_SET -> s.state == HslPlayState.SET;
            case MOTION_IN_STOP -> s.stopped;
            default -> true;
        };
    }

    @Override
    public void apply(HslState s) {
        HslTeam t = s.team(team);
        HslPlayer p = t.player(player);
        HslPenalty penalty = call;
        if (call == HslPenalty.CAUTIONED && p.cautions >= 1) {
            penalty = HslPenalty.SENT_OFF;
        }
        if (penalty == HslPenalty.SENT_OFF) {
            p.penalise(HslPenalty.SENT_OFF, 0, false);
            p.cautions = 0;
            if (t.goalkeeper == player) {
                t.goalkeeper = 0;
            }
            return;
        }
        if (penalty == HslPenalty.CAUTIONED) {
            p.cautions++;
        }
        if (penalty == HslPenalty.MOTION_IN_SET) {
            p.penalise(penalty, s.rules.motionInSetMs(), true);
        } else if (penalty == HslPenalty.PICK_UP && (s.state == HslPlayState.INITIAL
                || s.state == HslPlayState.TIMEOUT || s.state == HslPlayState.FINISHED)) {
            p.penalise(penalty, 0, true);
        } else {
            long ms = s.rules.penaltyMs();
            if (s.rules.incremental().contains(penalty)) {
                ms += t.incrementalPenalties * s.rules.penaltyIncrementMs();
                t.incrementalPenalties++;
            }
            p.penalise(penalty, ms, false);
        }
    }

    @Override
    public String describe() {
        return "penalize " + team + " " + player + " " + call.name().toLowerCase(Locale.ROOT);
    }
}
