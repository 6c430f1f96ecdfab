package touchline.game;

import java.util.Locale;

/**
 * The text form of referee actions, shared by the CLI and scripts (one command per line); the
 * commands are listed in {@link #HELP}, e.g. {@code goal 13}, {@code penalty 7 2 physical_contact},
 * {@code freekick 13 direct}. {@code undo}, {@code status} and {@code quit} are handled by the
 * caller, since they are not actions.
 */
public final class ActionSyntax {

    /**
     * A parsed line: an action, or an error text.
     *
     * @param action the action, null on error
     * @param error  what is wrong with the line, null when parsed
     */
    public record Parsed(LeagueAction<? super GameState> action, String error) {
        static Parsed error(String text) {
            return new Parsed(null, text);
        }
    }

    /** Help text, lines under 80 columns (the CLI prints it as is). */
    public static final String HELP = """
            ready | set | play | finish   state changes (during a set play "ready" is
                                          the set-play READY)
            goal TEAM                     goal for TEAM (team number)
            kickoff TEAM                  who kicks off (before the first kick-off)
            penalty TEAM PLAYER KIND      KIND: physical_contact ball_manipulation
                                          illegal_attack illegal_defense
                                          pickup_or_incapable service manual
            unpenalise TEAM PLAYER
            card TEAM PLAYER KIND         KIND: warning yellow red
            substitute TEAM OUT IN        substitute IN replaces player OUT
            goalkeeper TEAM PLAYER
            freekick TEAM direct|indirect
            penaltykick|corner|goalkick|throwin TEAM
            prepare | execute | abort     set-play steps (also "setplay ready")
            dropball
            timeout TEAM                  "ready" ends the timeout
            penaltyshootout               after a drawn 2nd half; per kick: set,
                                          play, then goal TEAM or finish
            undo | status | quit""";

    /** Parses one line against the current state (which decides what "ready" means). */
    public Parsed parse(String line, GameState state) {
        String[] w = line.trim().toLowerCase(Locale.ROOT).split("\\s+");
        if (w.length == 0 || w[0].isEmpty()) {
            return Parsed.error("empty command");
        }
        try {
            return switch (w[0]) {
                case "ready" -> new Parsed(state.state() == PlayState.PLAYING && state.secondary().isSetPlay()
                        ? new SetPlayStep(SetPlayStep.Step.READY) : new ToReady(), null);
                case "set" -> args(w, 0, new ToSet());
                case "play", "playing" -> args(w, 0, new ToPlaying());
                case "finish", "finished" -> args(w, 0, new ToFinished());
                case "goal" -> args(w, 1, new Goal(num(w[1])));
                case "kickoff" -> args(w, 1, new SetKickOff(num(w[1])));
                case "penalty", "penalise", "penalize" -> penalty(w);
                case "unpenalise", "unpenalize" -> args(w, 2, new Unpenalize(num(w[1]), num(w[2])));
                case "card" -> card(w);
                case "substitute" -> args(w, 3, new Substitute(num(w[1]), num(w[2]), num(w[3])));
                case "goalkeeper" -> args(w, 2, new SetGoalkeeper(num(w[1]), num(w[2])));
                case "freekick" -> freeKick(w);
                case "penaltykick" -> args(w, 1, new StartSetPlay(num(w[1]), SecondaryState.PENALTYKICK));
                case "corner", "cornerkick" -> args(w, 1, new StartSetPlay(num(w[1]), SecondaryState.CORNER_KICK));
                case "goalkick" -> args(w, 1, new StartSetPlay(num(w[1]), SecondaryState.GOAL_KICK));
                case "throwin" -> args(w, 1, new StartSetPlay(num(w[1]), SecondaryState.THROW_IN));
                case "setplay" -> w.length == 2 && w[1].equals("ready")
                        ? new Parsed(new SetPlayStep(SetPlayStep.Step.READY), null)
                        : Parsed.error("usage: setplay ready");
                case "prepare" -> args(w, 0, new SetPlayStep(SetPlayStep.Step.PREPARE));
                case "execute" -> args(w, 0, new SetPlayStep(SetPlayStep.Step.EXECUTE));
                case "abort" -> args(w, 0, new SetPlayStep(SetPlayStep.Step.ABORT));
                case "dropball", "droppedball" -> args(w, 0, new DropBall());
                case "timeout" -> args(w, 1, new Timeout(num(w[1])));
                case "penaltyshootout", "pso" -> args(w, 0, new StartPenaltyShootout());
                default -> Parsed.error("unknown command '" + w[0] + "'");
            };
        } catch (ArrayIndexOutOfBoundsException e) {
            return Parsed.error("missing argument for '" + w[0] + "'");
        } catch (NumberFormatException e) {
            return Parsed.error("not a number in '" + line.trim() + "'");
        }
    }

    private static Parsed args(String[] w, int expected, LeagueAction<? super GameState> a) {
        return w.length - 1 == expected ? new Parsed(a, null)
                : Parsed.error("'" + w[0] + "' takes " + expected + " argument(s), got " + (w.length - 1));
    }

    private static int num(String s) {
        return Integer.parseInt(s);
    }

    private static Parsed penalty(String[] w) {
        Penalty p = Penalty.parse(w[3]);
        if (p == null || p == Penalty.NONE || p == Penalty.SUBSTITUTE) {
            return Parsed.error("unknown penalty '" + w[3] + "'");
        }
        return args(w, 3, new Penalize(num(w[1]), num(w[2]), p));
    }

    private static Parsed card(String[] w) {
        Card.Kind kind = switch (w[3]) {
            case "warning", "warn" -> Card.Kind.WARNING;
            case "yellow" -> Card.Kind.YELLOW;
            case "red" -> Card.Kind.RED;
            default -> null;
        };
        return kind == null ? Parsed.error("card kind must be warning, yellow or red")
                : args(w, 3, new Card(num(w[1]), num(w[2]), kind));
    }

    private static Parsed freeKick(String[] w) {
        String kind = w.length > 2 ? w[2] : "direct";
        SecondaryState s = switch (kind) {
            case "direct" -> SecondaryState.DIRECT_FREEKICK;
            case "indirect" -> SecondaryState.INDIRECT_FREEKICK;
            default -> null;
        };
        if (s == null || w.length > 3) {
            return Parsed.error("usage: freekick TEAM direct|indirect");
        }
        return new Parsed(new StartSetPlay(num(w[1]), s), null);
    }
}
