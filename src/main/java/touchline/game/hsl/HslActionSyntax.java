package touchline.game.hsl;

import touchline.game.Goal;
import touchline.game.LeagueAction;
import touchline.game.StartPenaltyShootout;
import touchline.protocol.gamecontroller.HslPenalty;

import java.util.Locale;

/**
 * The text form of HSL referee actions for the CLI and scripts, one per line, listed in
 * {@link #HELP}: the official GameController's buttons under short names ({@code kickoff 5},
 * {@code corner 14}, {@code stop}, {@code penalize 14 3 pushing}, {@code unpenalize 14 3}, ...).
 * {@code undo}, {@code status} and {@code quit} are the caller's.
 */
public final class HslActionSyntax {

    /**
     * A parsed line: an action, or what is wrong with it.
     *
     * @param action the action, null on error
     * @param error  the error text, null when parsed
     */
    public record Parsed(LeagueAction<? super HslState> action, String error) {
        static Parsed error(String text) {
            return new Parsed(null, text);
        }
    }

    /** Help text, lines under 80 columns. */
    public static final String HELP = """
            kickoff TEAM                 READY for TEAM's kick-off (from INITIAL or a
                                         timeout)
            set | play                   READY -> SET, the whistle SET -> PLAYING
                                         (robots see SET 10 s longer)
            stop | resume                stop play / resume (Space in the official GC)
            directfreekick|indirectfreekick|throwin|goalkick|corner TEAM
                                         set play without READY: play stops, 45 s
                                         count from "resume"
            penaltykick TEAM             READY/SET/PLAYING with 60 s for the kick
            ballfree                     the running set play is over
            goal TEAM
            timeout TEAM | timeout referee
            droppedball                  global game stuck: READY, no kicking team
            penalize TEAM PLAYER CALL    CALL: illegal_positioning motion_in_set
                                         motion_in_stop local_game_stuck
                                         incapable_robot pick_up ball_holding
                                         leaving_the_field arms_hands pushing
                                         caution send_off
            unpenalize TEAM PLAYER [force]  1st: start the timer (robot outside),
                                         after it ran out: back in; force: at once
            additionalminute             +60 s and +600 messages per team
            finish                       end of the half (2nd half begins 300 s
                                         into the break, or "secondhalf")
            secondhalf
            extratime                    after a drawn 2nd half: 2 x 300 s
            penaltyshootout TEAM         after a drawn 2nd half, TEAM shoots first;
                                         "shooter TEAM PLAYER [goalkeeper]" for
                                         both teams, then per shot: shot, play,
                                         goal TEAM or missed (or its 60 s run out)
            goalkeeper TEAM PLAYER       0 = none
            teammessage TEAM [BYTES]     count a team message (as if heard)
            undo | status | quit""";

    /** Parses one line. */
    public Parsed parse(String line) {
        String[] w = line.trim().toLowerCase(Locale.ROOT).split("\\s+");
        if (w.length == 0 || w[0].isEmpty()) {
            return Parsed.error("empty command");
        }
        try {
            return switch (w[0]) {
                case "kickoff" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.KICK_OFF));
                case "set" -> args(w, 0, new WaitForSetPlay());
                case "play", "playing" -> args(w, 0, new FreeSetPlay());
                case "stop" -> args(w, 0, new StopPlay(false));
                case "resume" -> args(w, 0, new StopPlay(true));
                case "directfreekick" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.DIRECT_FREE_KICK));
                case "indirectfreekick" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.INDIRECT_FREE_KICK));
                case "throwin" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.THROW_IN));
                case "goalkick" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.GOAL_KICK));
                case "corner", "cornerkick" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.CORNER_KICK));
                case "penaltykick" -> args(w, 1, new HslStartSetPlay(num(w[1]), SetPlay.PENALTY_KICK));
                case "ballfree" -> args(w, 0, new FinishSetPlay());
                case "goal" -> args(w, 1, new Goal(num(w[1])));
                case "timeout" -> args(w, 1, new HslTimeout(w[1].equals("referee") ? HslTimeout.REFEREE : num(w[1])));
                case "droppedball", "gamestuck" -> args(w, 0, new GlobalGameStuck());
                case "penalize", "penalise" -> penalize(w);
                case "caution" -> args(w, 2, new HslPenalize(num(w[1]), num(w[2]), HslPenalty.CAUTIONED));
                case "sendoff" -> args(w, 2, new HslPenalize(num(w[1]), num(w[2]), HslPenalty.SENT_OFF));
                case "unpenalize", "unpenalise" -> unpenalize(w);
                case "additionalminute", "addtime", "extraminute" -> args(w, 0, new AddAdditionalTime());
                case "finish", "finishhalf" -> args(w, 0, new FinishHalf());
                case "secondhalf" -> args(w, 0, new SwitchHalf());
                case "penaltyshootout", "pso" -> args(w, 1, new StartPenaltyShootout(num(w[1])));
                case "shot" -> args(w, 0, new PenaltyShot());
                case "extratime" -> args(w, 0, new StartExtraTime());
                case "shooter" -> w.length == 4 && w[3].equals("goalkeeper")
                        ? new Parsed(new SelectShooter(num(w[1]), num(w[2]), true), null)
                        : args(w, 2, new SelectShooter(num(w[1]), num(w[2]), false));
                case "missed", "miss" -> args(w, 0, new FinishPenaltyShot());
                case "goalkeeper" -> args(w, 2, new SelectGoalkeeper(num(w[1]), num(w[2])));
                case "teammessage" -> w.length == 2 ? new Parsed(new TeamMessage(num(w[1]), 1), null)
                        : args(w, 2, new TeamMessage(num(w[1]), w.length > 2 ? num(w[2]) : 1));
                default -> Parsed.error("unknown command '" + w[0] + "' (see --help)");
            };
        } catch (ArrayIndexOutOfBoundsException e) {
            return Parsed.error("missing argument for '" + w[0] + "'");
        } catch (NumberFormatException e) {
            return Parsed.error("not a number in '" + line.trim() + "'");
        }
    }

    private static Parsed args(String[] w, int expected, LeagueAction<? super HslState> a) {
        return w.length - 1 == expected ? new Parsed(a, null)
                : Parsed.error("'" + w[0] + "' takes " + expected + " argument(s), got " + (w.length - 1));
    }

    private static int num(String s) {
        return Integer.parseInt(s);
    }

    private static Parsed penalize(String[] w) {
        HslPenalty call = w.length > 3 ? call(w[3]) : null;
        if (w.length > 3 && call == null) {
            return Parsed.error("unknown call '" + w[3] + "'");
        }
        return args(w, 3, call == null ? null : new HslPenalize(num(w[1]), num(w[2]), call));
    }

    /** The penalty a call names (official spellings, and caution / send_off / arms_hands). */
    static HslPenalty call(String name) {
        String n = name.replace('-', '_');
        switch (n) {
            case "caution":
                return HslPenalty.CAUTIONED;
            case "send_off", "sendoff":
                return HslPenalty.SENT_OFF;
            case "arms_hands", "playing_with_arms_hands":
                return HslPenalty.PLAYING_WITH_ARMS_HANDS;
            default:
                for (HslPenalty p : HslPenalty.values()) {
                    if (p != HslPenalty.NONE && p != HslPenalty.SUBSTITUTE && p.name().equalsIgnoreCase(n)) {
                        return p;
                    }
                }
                return null;
        }
    }

    private static Parsed unpenalize(String[] w) {
        if (w.length == 4 && !w[3].equals("force")) {
            return Parsed.error("usage: unpenalize TEAM PLAYER [force]");
        }
        boolean force = w.length == 4;
        return w.length == 3 || w.length == 4 ? new Parsed(new HslUnpenalize(num(w[1]), num(w[2]), force), null)
                : Parsed.error("usage: unpenalize TEAM PLAYER [force]");
    }
}
