package touchline.transport;

/**
 * Why nothing but GameController packets may go to robots now ({@link SendGate}), and whether it
 * passes: match mode holds while play lasts ({@link #untilPlayStops}); a console viewing a remote
 * Touchline holds for good ({@link #always}). Each sender says it in its own words: a debug
 * request the console asks again for {@linkplain #queued goes out when play stops}, a NAO command
 * is {@linkplain #dropped not sent}.
 */
public record Hold(String why, boolean untilPlayStops) {

    public static Hold untilPlayStops(String why) {
        return new Hold(why, true);
    }

    public static Hold always(String why) {
        return new Hold(why, false);
    }

    /** For what is asked for again later (debug requests): "match mode, PLAYING; goes out when play stops". */
    public String queued() {
        return untilPlayStops ? why + "; goes out when play stops" : why;
    }

    /** For what is dropped when held (NAO commands): "match mode, PLAYING; not sent". */
    public String dropped() {
        return untilPlayStops ? why + "; not sent" : why;
    }
}
