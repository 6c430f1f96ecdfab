package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslSetPlay;

import java.util.Locale;

/**
 * The set plays the referee starts. A kick-off and a penalty kick begin with READY and SET; the
 * others begin with play stopped where it is. A kick-off goes out on the wire as no set play
 * with the kicking team set.
 */
public enum SetPlay {
    KICK_OFF(HslSetPlay.NONE, true),
    DIRECT_FREE_KICK(HslSetPlay.DIRECT_FREE_KICK, false),
    INDIRECT_FREE_KICK(HslSetPlay.INDIRECT_FREE_KICK, false),
    PENALTY_KICK(HslSetPlay.PENALTY_KICK, true),
    THROW_IN(HslSetPlay.THROW_IN, false),
    GOAL_KICK(HslSetPlay.GOAL_KICK, false),
    CORNER_KICK(HslSetPlay.CORNER_KICK, false);

    private final HslSetPlay wire;
    private final boolean withReady;

    SetPlay(HslSetPlay wire, boolean withReady) {
        this.wire = wire;
        this.withReady = withReady;
    }

    public HslSetPlay wire() {
        return wire;
    }

    /** Whether robots get READY and SET first (kick-off, penalty kick); else play stops. */
    public boolean withReady() {
        return withReady;
    }

    /** How long the set play lasts after the whistle (or after resuming). */
    long durationMs(HslRules rules) {
        return switch (this) {
            case KICK_OFF -> rules.kickOffMs();
            case PENALTY_KICK -> rules.penaltyKickMs();
            default -> rules.setPlayMs();
        };
    }

    public String label() {
        return name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }
}
