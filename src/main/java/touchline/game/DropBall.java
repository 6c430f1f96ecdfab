package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;

/** Dropped ball: back to READY with no kicking team (and no ball-free countdown at PLAYING). */
public record DropBall() implements Action {
    @Override
    public boolean isLegal(GameState s) {
        return s.state == PlayState.PLAYING && !s.isPenaltyShootout();
    }

    @Override
    public void apply(GameState s, long nowMs) {
        s.kickOffTeam = GameControlData.DROP_BALL;
        s.endSetPlay();
        s.block(0, nowMs);
        s.enter(PlayState.READY, nowMs);
    }

    @Override
    public String describe() {
        return "dropball";
    }
}
