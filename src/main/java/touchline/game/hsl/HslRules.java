package touchline.game.hsl;

import touchline.protocol.gamecontroller.HslPenalty;

import java.util.EnumSet;
import java.util.Set;

/**
 * The rule parameters of one HSL GameController release, as in its {@code params.yaml}; times
 * in milliseconds. {@link #v7(Competition)} is 7.0.0 (protocol version 20, RoboCup 2026),
 * {@link #v6(Competition)} is 6.0.1 (version 19, German Open 2026), which differs in penalty
 * times, in stopping the game clock while play is stopped, and in having no cautions and no
 * motion in stop.
 *
 * @param competition            division and team size
 * @param protocolVersion        19 or 20
 * @param halfMs                 length of a half
 * @param halfTimeBreakMs        half-time break (shown counting down, negative when exceeded)
 * @param switchHalfAfterMs      the second half begins by itself this long after the first ended
 * @param extraHalfMs            half of extra time
 * @param timeoutMs              team timeout
 * @param timeoutsPerTeam        team timeouts per game
 * @param refereeTimeoutMs       referee timeout
 * @param readyMs                READY before a kick-off or penalty kick
 * @param kickOffMs              kick-off set play after the whistle
 * @param penaltyKickMs          penalty kick set play after the whistle
 * @param setPlayMs              free kicks, throw-in, goal kick, corner kick
 * @param delayAfterPlayingMs    robots keep seeing the state before a PLAYING whistle this long
 * @param messageBudget          team messages per team and game
 * @param messagesPerAddedMinute added to each budget per minute of additional time
 * @param messagesExtraTime      added to each budget for extra time
 * @param maxMessageBytes        longest legal team message
 * @param mercyGoals             goal difference that ends the game
 * @param penaltyShots           regular shots per team in a shoot-out
 * @param suddenDeathShots       further shots per team
 * @param penaltyShotMs          time for one shot
 * @param penaltyMs              a removal penalty
 * @param penaltyIncrementMs     added for each earlier incremental penalty of the team
 * @param motionInSetMs          motion in set (removed by itself)
 * @param incremental            penalties that count for the increment
 * @param clockRunsWhileStopped  7.x: the game clock runs while play is stopped (6.0.x: it stops)
 * @param cautions               7.x: cautions and send-offs can be called (6.0.1: disabled)
 * @param firstHalfInExtraTime   7.x: firstHalf is also 1 in the first half of extra time
 */
public record HslRules(Competition competition, int protocolVersion, long halfMs, long halfTimeBreakMs,
                       long switchHalfAfterMs, long extraHalfMs, long timeoutMs, int timeoutsPerTeam,
                       long refereeTimeoutMs, long readyMs, long kickOffMs, long penaltyKickMs, long setPlayMs,
                       long delayAfterPlayingMs, int messageBudget, int messagesPerAddedMinute,
                       int messagesExtraTime, int maxMessageBytes, int mercyGoals, int penaltyShots,
                       int suddenDeathShots, long penaltyShotMs, long penaltyMs, long penaltyIncrementMs,
                       long motionInSetMs, Set<HslPenalty> incremental, boolean clockRunsWhileStopped,
                       boolean cautions, boolean firstHalfInExtraTime) {

    /** Jersey numbers 1..20 exist; those above playersPerTeam start as substitutes. */
    public static final int MAX_PLAYERS = 20;

    public HslRules {
        incremental = Set.copyOf(incremental);
    }

    /** GameController 7.0.0 (7.0.0-rc.3, {@code a6bb00a}), protocol version 20. */
    public static HslRules v7(Competition competition) {
        return new HslRules(competition, 20, 600_000, 600_000, 300_000, 300_000, 300_000, 1, 600_000, 45_000,
                10_000, 60_000, 45_000, 10_000, 12_000, 600, 6_000, 512, 10, 3, 3, 60_000, 45_000, 10_000, 15_000,
                EnumSet.of(HslPenalty.MOTION_IN_STOP, HslPenalty.BALL_HOLDING, HslPenalty.LEAVING_THE_FIELD,
                        HslPenalty.PLAYING_WITH_ARMS_HANDS, HslPenalty.PUSHING, HslPenalty.CAUTIONED),
                true, true, true);
    }

    /**
     * GameController 6.0.1 ({@code v6.0.1}, German Open 2026), protocol version 19. Its budget for
     * extra time is not known (its "extra minute" is the added minute), so none is added.
     */
    public static HslRules v6(Competition competition) {
        return new HslRules(competition, 19, 600_000, 600_000, 300_000, 300_000, 300_000, 1, 600_000, 45_000,
                10_000, 60_000, 45_000, 10_000, 12_000, 600, 0, 512, 10, 3, 3, 60_000, 30_000, 15_000, 10_000,
                EnumSet.of(HslPenalty.ILLEGAL_POSITIONING, HslPenalty.PICK_UP, HslPenalty.BALL_HOLDING,
                        HslPenalty.LEAVING_THE_FIELD, HslPenalty.PLAYING_WITH_ARMS_HANDS, HslPenalty.PUSHING),
                false, false, false);
    }

    /** The release that sends this protocol version (19 or 20), null for another. */
    public static HslRules forVersion(int version, Competition competition) {
        return version == 20 ? v7(competition) : version == 19 ? v6(competition) : null;
    }

    /** Whether this release knows the penalty (v19 has no motion in stop and no caution). */
    public boolean knows(HslPenalty penalty) {
        return cautions || (penalty != HslPenalty.MOTION_IN_STOP && penalty != HslPenalty.CAUTIONED);
    }
}
