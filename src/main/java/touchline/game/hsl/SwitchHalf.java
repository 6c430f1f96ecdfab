package touchline.game.hsl;

/**
 * Begins the second half before the GameController does it by itself: INITIAL, sides swapped,
 * the other team's kick-off, penalties lifted except send-offs and substitutes.
 */
public record SwitchHalf() implements HslAction {
    @Override
    public boolean isLegal(HslState s) {
        return s.state == HslPlayState.FINISHED && s.firstHalf && s.phase != HslPhase.PENALTY_SHOOT_OUT;
    }

    @Override
    public void apply(HslState s) {
        s.switchHalf();
    }

    @Override
    public String describe() {
        return "second half";
    }
}
