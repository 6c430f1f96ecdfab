package touchline.game.hsl;

/**
 * Starts a set play for {@code team}. A kick-off (from INITIAL or a timeout, for the team whose
 * kick-off it is) and a penalty kick (during play) go to READY; the others keep PLAYING and
 * stop play, their 45 s beginning only when the referee resumes.
 */
public record HslStartSetPlay(int team, SetPlay kind) implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        if (s.team(team) == null || s.phase == HslPhase.PENALTY_SHOOT_OUT) {
            return false;
        }
        if (kind == SetPlay.KICK_OFF) {
            return (s.state == HslPlayState.INITIAL || s.state == HslPlayState.TIMEOUT) && s.kickingTeam == team;
        }
        return s.state == HslPlayState.PLAYING;
    }

    @Override
    public void apply(HslState s) {
        if (kind.withReady()) {
            if (kind == SetPlay.PENALTY_KICK) {
                s.beginStoppage();
            }
            s.enterReady(kind, team);
            return;
        }
        s.setPlay = kind;
        s.kickingTeam = team;
        s.stopped = true;
        s.startSecondary(SecondaryTimer.SET_PLAY, kind.durationMs(s.rules));
    }

    @Override
    public String describe() {
        return kind.label() + " " + team;
    }
}
