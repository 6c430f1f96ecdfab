package touchline.app.game;

import touchline.transport.gamecontroller.GcSender;

/**
 * What became of the real-time priority asked for the embedded GameController's sender, as a
 * value a face switches on ({@link EmbeddedGameController#senderPriority()}) instead of
 * comparing the transport's words: granted, not asked for, not tried yet, or refused with the
 * system's reason ({@code why}, "" unless refused).
 */
public record SenderPriority(Kind kind, String why) {

    public enum Kind { REAL_TIME, NOT_REQUESTED, STARTING, REFUSED }

    /** The sender's outcome in words ({@link GcSender#realtimeOutcome()}) as a value. */
    static SenderPriority of(String outcome) {
        if (outcome.isEmpty()) {
            return new SenderPriority(Kind.REAL_TIME, "");
        } else if (outcome.equals(GcSender.NOT_REQUESTED)) {
            return new SenderPriority(Kind.NOT_REQUESTED, "");
        } else if (outcome.equals(GcSender.NOT_STARTED)) {
            return new SenderPriority(Kind.STARTING, "");
        }
        return new SenderPriority(Kind.REFUSED, outcome);
    }
}
