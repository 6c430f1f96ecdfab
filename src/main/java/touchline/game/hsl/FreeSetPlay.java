package touchline.game.hsl;

/**
 * SET → PLAYING, the whistle. The clock of the half starts with its first kick-off; the
 * kick-off (10 s) or penalty kick (60 s) begins, a dropped ball has no kicking team and no set
 * play. Robots keep seeing the state before the whistle for the rules' delay.
 */
public record FreeSetPlay() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        if (s.state != HslPlayState.SET) {
            return false;
        }
        // in a shoot-out each team has exactly one player on the field: shooter and goalkeeper
        return s.phase != HslPhase.PENALTY_SHOOT_OUT
                || (SelectShooter.onField(s.teams[0]) == 1 && SelectShooter.onField(s.teams[1]) == 1);
    }

    @Override
    public void apply(HslState s) {
        s.holdForRobots();
        s.state = HslPlayState.PLAYING;
        if (s.phase == HslPhase.PENALTY_SHOOT_OUT) {
            return; // the shot's 60 s run from now
        }
        s.halfKickedOff = true;
        s.stoppageClockMs = -1;
        if (s.setPlay == null || s.kickingTeam == HslState.NO_TEAM) {
            s.endSetPlay();
        } else {
            s.startSecondary(SecondaryTimer.SET_PLAY, s.setPlay.durationMs(s.rules));
        }
    }

    @Override
    public String describe() {
        return "play";
    }
}
