package touchline.ui.frame;

/**
 * A line of text that changes at most twice a second: a count ("5 series · 512 points", "4 393
 * lines") that moves with every frame is read by nobody at 30 changes a second, and each change
 * makes JavaFX repaint the label and every background behind it. A change after a quiet half
 * second shows at once; one sooner waits for the next {@link #due} call at or after the half
 * second, so the last text always shows. Pure.
 */
public final class PacedText {

    /** The shortest time between two changes. */
    public static final long MIN_MICROS = 500_000;

    private String shown = "";
    private String pending;
    private long changedMicros = Long.MIN_VALUE / 2;

    /** The text as it should read now; returns the text to show, or {@code null} to leave the label as it is. */
    public String offer(String text, long nowMicros) {
        if (text.equals(shown)) {
            pending = null;
            return null;
        }
        pending = text;
        return due(nowMicros);
    }

    /** A text waiting for its turn, if its turn has come; {@code null} otherwise. */
    public String due(long nowMicros) {
        if (pending == null || nowMicros - changedMicros < MIN_MICROS) {
            return null;
        }
        shown = pending;
        pending = null;
        changedMicros = nowMicros;
        return shown;
    }
}
