package touchline.game;

/**
 * What became of an action handed to {@link Game}: applied, or refused with the reason.
 *
 * @param applied whether the state changed
 * @param message what happened, e.g. {@code goal 13} or {@code illegal now: play (state READY)}
 */
public record Outcome(boolean applied, String message) {
}
