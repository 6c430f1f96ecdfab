package touchline.transport;

/** What became of a command for a robot: sent, held back (match mode), or impossible. */
public record SendResult(Outcome outcome, String reason) {

    public enum Outcome { SENT, HELD, FAILED }

    public static SendResult sent() {
        return new SendResult(Outcome.SENT, "");
    }

    public static SendResult held(String reason) {
        return new SendResult(Outcome.HELD, reason);
    }

    public static SendResult failed(String reason) {
        return new SendResult(Outcome.FAILED, reason);
    }

    public boolean isSent() {
        return outcome == Outcome.SENT;
    }

    /** In words for a status line: "sent", "held back: …", "not sent: …". */
    public String describe() {
        return switch (outcome) {
            case SENT -> "sent";
            case HELD -> "held back: " + reason;
            case FAILED -> "not sent: " + reason;
        };
    }
}
