package touchline.game;

/** The primary game state, with its wire code (identical in every GameController format). */
public enum PlayState {
    INITIAL, READY, SET, PLAYING, FINISHED;

    public int code() {
        return ordinal();
    }
}
