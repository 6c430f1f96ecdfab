package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslPenalty;

/**
 * One jersey of an HSL team. A removal penalty's timer does not start with the call: the
 * operator starts it once the robot is outside ({@link #timerStarted}), it counts down in
 * READY and PLAYING, and at 0 the robot stays penalised until the operator unpenalises it;
 * only motion in set starts at once and ends by itself.
 */
public final class HslPlayer {

    HslPenalty penalty = HslPenalty.NONE;
    boolean timerStarted;
    long penaltyMs;
    /** The duration the timer starts with (fixed when the penalty was called). */
    long penaltyDurationMs;
    int cautions;
    int warnings;

    HslPlayer copy() {
        HslPlayer p = new HslPlayer();
        p.penalty = penalty;
        p.timerStarted = timerStarted;
        p.penaltyMs = penaltyMs;
        p.penaltyDurationMs = penaltyDurationMs;
        p.cautions = cautions;
        p.warnings = warnings;
        return p;
    }

    public HslPenalty penalty() {
        return penalty;
    }

    public boolean isPenalised() {
        return penalty != HslPenalty.NONE;
    }

    public boolean timerStarted() {
        return timerStarted;
    }

    public int cautions() {
        return cautions;
    }

    /** Whole seconds left, rounded up, 0..255; 0 before the timer starts. */
    public int secsTillUnpenalised() {
        if (!timerStarted || penaltyMs <= 0) {
            return 0;
        }
        return (int) Math.min(255, HslState.ceilSeconds(penaltyMs));
    }

    void penalise(HslPenalty p, long durationMs, boolean startNow) {
        penalty = p;
        penaltyDurationMs = durationMs;
        timerStarted = startNow;
        penaltyMs = durationMs;
    }

    void unpenalise() {
        penalty = HslPenalty.NONE;
        timerStarted = false;
        penaltyMs = 0;
        penaltyDurationMs = 0;
    }

    /** Whether the penalty keeps the robot off the field for the rest of the game or half. */
    boolean permanent() {
        return penalty == HslPenalty.SENT_OFF || penalty == HslPenalty.SUBSTITUTE;
    }
}
