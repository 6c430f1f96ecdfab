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
}
