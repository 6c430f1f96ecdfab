package touchline.game.hsl;

import java.util.ArrayList;
import java.util.List;

/**
 * The script of the official golden games (golden/gamecontroller/hsl20 and hsl19, README
 * "Files: game fields"): what the operator did at which simulated time, in our CLI syntax, and
 * which step file shows the result at which send instant. Teams: home 5 (red / purple
 * goalkeeper) on the left with the first kick-off, away 14 (blue / yellow), Middle Advanced.
 */
public final class HslGoldenScript {

    /**
     * @param file     step file, or null for an action without a file of its own
     * @param atMs     when the commands are applied
     * @param sentAtMs when the step file was sent
     * @param commands CLI lines
     */
    public record Step(String file, long atMs, long sentAtMs, List<String> commands) {
    }

    /** Lines of {@link #V20} that the version 19 script shares (up to 20-playing-after-delay). */
    private static final int SHARED_WITH_V19 = 25;

    private HslGoldenScript() {
    }

    private static final String[] V20 = {
            "00-initial.bin|0|0|",
            "01-kickoff-team5-ready.bin|10250|10500|kickoff 5",
            "02-ready-after-10s.bin|20250|20500|",
            "-|21250|-|teammessage 5",
            "-|21350|-|teammessage 5",
            "-|21450|-|teammessage 5",
            "-|22250|-|teammessage 14",
            "03-ready-after-team-messages.bin|23250|23500|",
            "04-set.bin|30250|30500|set",
            "05-playing-delayed.bin|35250|35500|play",
            "06-playing-delayed-after-5s.bin|40250|40500|",
            "07-playing-after-delay.bin|45250|45500|",
            "08-corner-kick-team14-stopped.bin|60250|60250|corner 14",
            "09-corner-kick-stopped-after-5s.bin|65250|65550|",
            "10-corner-kick-resumed.bin|70250|70550|resume",
            "11-corner-kick-after-10s.bin|80250|80550|",
            "12-corner-kick-ball-free.bin|85250|85550|ballfree",
            "13-goal-team5.bin|90250|90550|goal 5",
            "14-timeout-team14.bin|100250|100550|timeout 14",
            "15-timeout-after-20s.bin|120250|120550|",
            "16-kickoff-team5-ready.bin|130250|130550|kickoff 5",
            "17-set.bin|140250|140550|set",
            "18-motion-in-set-team14-player2.bin|142250|142550|penalize 14 2 motion_in_set",
            "19-playing-delayed.bin|145250|145550|play",
            "20-playing-after-delay.bin|155250|155550|",
            "21-motion-in-set-served.bin|160250|160550|",
            "22-pushing-team14-player3.bin|170250|170550|penalize 14 3 pushing",
            "23-pushing-timer-started.bin|180250|180550|unpenalize 14 3",
            "24-pushing-after-20s.bin|200250|200550|",
            "25-pushing-timer-elapsed.bin|226250|226550|",
            "26-pushing-unpenalized.bin|230250|230550|unpenalize 14 3",
            "27-caution-team5-player2.bin|240250|240550|penalize 5 2 caution",
            "28-direct-free-kick-team14-stopped.bin|245250|245250|directfreekick 14",
            "29-direct-free-kick-resumed.bin|250250|250550|resume",
            "30-direct-free-kick-expired.bin|295250|295550|",
            "31-stop-play.bin|300250|300250|stop",
            "32-motion-in-stop-team5-player4.bin|302250|302550|penalize 5 4 motion_in_stop",
            "33-resume-play.bin|305250|305550|resume",
            "34-second-caution-team5-player2.bin|310250|310550|penalize 5 2 caution",
            "35-goal-team14.bin|320250|320550|goal 14",
            "36-additional-minute.bin|325250|325550|additionalminute",
            "37-finished-first-half.bin|335250|335550|finish",
            "38-half-time-break-after-10s.bin|345250|345550|",
            "39-second-half-initial.bin|635250|635550|",
            "40-second-half-kickoff-team14-ready.bin|645250|645550|kickoff 14",
            "41-second-half-set.bin|655250|655550|set",
            "42-second-half-playing-delayed.bin|660250|660550|play",
            "43-second-half-playing.bin|670250|670550|",
            "44-global-game-stuck-ready.bin|690250|690550|droppedball",
            "45-dropped-ball-set.bin|700250|700550|set",
            "46-dropped-ball-playing-delayed.bin|705250|705550|play",
            "47-dropped-ball-playing.bin|715250|715550|",
            "48-penalty-kick-team5-ready.bin|730250|730550|penaltykick 5",
            "49-penalty-kick-set.bin|740250|740550|set",
            "50-penalty-kick-playing-delayed.bin|745250|745550|play",
            "51-penalty-kick-playing.bin|755250|755550|",
            "52-goal-team5.bin|760250|760550|goal 5",
            "53-finished.bin|790250|790550|finish",
    };

    /** Version 19 after the steps it shares with version 20 (the first 25 lines). */
    private static final String[] V19_AFTER_SHARED = {
            "21-pushing-team14-player3.bin|170250|170550|penalize 14 3 pushing",
            "22-pushing-timer-started.bin|180250|180550|unpenalize 14 3",
            "23-pushing-after-20s.bin|200250|200550|",
            "24-pushing-timer-elapsed.bin|211250|211550|",
            "25-pushing-unpenalized.bin|215250|215550|unpenalize 14 3",
            "26-arms-hands-team5-player2.bin|240250|240550|penalize 5 2 arms_hands",
            "27-direct-free-kick-team14-stopped.bin|245250|245250|directfreekick 14",
            "28-direct-free-kick-resumed.bin|250250|250550|resume",
            "29-direct-free-kick-expired.bin|295250|295550|",
            "30-stop-play.bin|300250|300250|stop",
            "31-incapable-robot-team5-player4.bin|302250|302550|penalize 5 4 incapable_robot",
            "32-resume-play.bin|305250|305550|resume",
            "33-goal-team14.bin|320250|320550|goal 14",
            "34-extra-minute.bin|325250|325550|additionalminute",
            "35-finished-first-half.bin|335250|335550|finish",
            "36-half-time-break-after-10s.bin|345250|345550|",
            "37-second-half-initial.bin|635250|635550|",
            "38-second-half-kickoff-team14-ready.bin|645250|645550|kickoff 14",
            "39-second-half-set.bin|655250|655550|set",
            "40-second-half-playing-delayed.bin|660250|660550|play",
            "41-second-half-playing.bin|670250|670550|",
            "42-global-game-stuck-ready.bin|690250|690550|droppedball",
            "43-dropped-ball-set.bin|700250|700550|set",
            "44-dropped-ball-playing-delayed.bin|705250|705550|play",
            "45-dropped-ball-playing.bin|715250|715550|",
            "46-penalty-kick-team5-ready.bin|730250|730550|penaltykick 5",
            "47-penalty-kick-set.bin|740250|740550|set",
            "48-penalty-kick-playing-delayed.bin|745250|745550|play",
            "49-penalty-kick-playing.bin|755250|755550|",
            "50-goal-team5.bin|760250|760550|goal 5",
            "51-finished.bin|790250|790550|finish",
    };

    /** The script of {@code hsl20} (version 20) or {@code hsl19}. */
    public static List<Step> of(int version) {
        List<Step> steps = new ArrayList<>();
        List<String> lines = new ArrayList<>(List.of(V20));
        if (version == 19) {
            lines = new ArrayList<>(lines.subList(0, SHARED_WITH_V19));
            lines.addAll(List.of(V19_AFTER_SHARED));
        }
        for (String line : lines) {
            String[] f = line.split("\\|", -1);
            List<String> commands = f[3].isEmpty() ? List.of() : List.of(f[3].split(";"));
            steps.add(new Step(f[0].equals("-") ? null : f[0], Long.parseLong(f[1]),
                    f[2].equals("-") ? -1 : Long.parseLong(f[2]), commands));
        }
        return steps;
    }
}
