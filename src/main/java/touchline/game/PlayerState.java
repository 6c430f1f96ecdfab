package touchline.game;

/**
 * One robot's referee record: its current penalty (with when it began and how long it lasts),
 * warnings, cards and goalkeeper flag. Mutable; owned by a {@link TeamState}.
 */
public final class PlayerState {

    Penalty penalty = Penalty.NONE;
    long penaltySinceMs;
    int penaltySeconds;
    int warnings;
    int yellowCards;
    int redCards;
    boolean goalkeeper;

    PlayerState copy() {
        PlayerState p = new PlayerState();
        p.penalty = penalty;
        p.penaltySinceMs = penaltySinceMs;
        p.penaltySeconds = penaltySeconds;
        p.warnings = warnings;
        p.yellowCards = yellowCards;
        p.redCards = redCards;
        p.goalkeeper = goalkeeper;
        return p;
    }

    void penalise(Penalty p, long nowMs, int seconds) {
        penalty = p;
        penaltySinceMs = nowMs;
        penaltySeconds = p.timed() ? seconds : 0;
    }

    void unpenalise() {
        penalty = Penalty.NONE;
        penaltySeconds = 0;
    }

    public Penalty penalty() {
        return penalty;
    }

    public boolean isPenalised() {
        return penalty != Penalty.NONE && penalty != Penalty.SUBSTITUTE;
    }

    /** Whole seconds until a timed penalty ends (never negative), 0 for untimed ones. */
    public int secsTillUnpenalised(long nowMs) {
        if (!penalty.timed()) {
            return 0;
        }
        return Math.max(0, GameState.remaining(penaltySeconds, penaltySinceMs, nowMs));
    }

    public int warnings() {
        return warnings;
    }

    public int yellowCards() {
        return yellowCards;
    }

    public int redCards() {
        return redCards;
    }

    public boolean goalkeeper() {
        return goalkeeper;
    }
}
