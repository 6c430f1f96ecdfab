package touchline.game.hsl;

/** Global game stuck, or the end of a referee timeout during play: READY for a dropped ball. */
public record GlobalGameStuck() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.phase != HslPhase.PENALTY_SHOOT_OUT && (s.state == HslPlayState.PLAYING
                || (s.state == HslPlayState.TIMEOUT && s.kickingTeam == HslState.NO_TEAM));
    }

    @Override
    public void apply(HslState s) {
        if (s.state == HslPlayState.PLAYING) {
            s.beginStoppage();
        }
        s.enterReady(SetPlay.KICK_OFF, HslState.NO_TEAM);
    }

    @Override
    public String describe() {
        return "dropped ball";
    }
}
