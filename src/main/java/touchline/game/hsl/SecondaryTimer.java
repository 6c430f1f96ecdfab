package touchline.game.hsl;

/** What the secondary clock counts, and whether it ends something when it reaches 0. */
enum SecondaryTimer {
    NONE(false),
    /** READY before a kick-off or penalty kick: at 0 the game goes to SET. */
    READY(true),
    /** A set play after its whistle (or after resuming): at 0 it is over. */
    SET_PLAY(true),
    /** Team or referee timeout: counts on below 0. */
    TIMEOUT(false),
    /** Half-time break: counts on below 0 (the second half begins by itself earlier). */
    HALF_TIME_BREAK(false);

    final boolean expires;

    SecondaryTimer(boolean expires) {
        this.expires = expires;
    }
}
