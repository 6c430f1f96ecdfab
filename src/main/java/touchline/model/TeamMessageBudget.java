package touchline.model;

import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.TeamInfo;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The budget guard: the team's own team messages (UDP 10000 + team number, heard by
 * {@code touchline.transport.TeamMessageListener}) against the active {@link RuleProfile}. It
 * counts the messages per team and per sender as the official GameController does (only in
 * READY, SET and PLAYING, not in a penalty shoot-out; before any GameController is heard the state
 * is not known, so messages are heard but not counted), takes the budget left from the
 * GameController's own count when a 2026 GameController is heard, measures the rate over the
 * last minute and forecasts when the budget runs out compared with the time left in the game,
 * warning before it does. A message over the profile's size limit is flagged at once with its
 * sender: under the 2026 rules one such message resets the team's score to 0. Subscribed to
 * the live stream only: a replay's messages are last match's, never this game's budget.
 */
public final class TeamMessageBudget implements EnvelopeSink {

    /** A forecast inside this share of the time left already warns ("well before it runs out"). */
    static final double WARNING_MARGIN = 1.10;
    private static final long WINDOW_MICROS = 60_000_000;
    private static final int BUCKETS = 12;

    public enum Verdict { NO_LIMIT, LIMIT_NOT_KNOWN, WAITING_FOR_MESSAGES, ON_TRACK, RUNS_OUT_BEFORE_THE_END, EXHAUSTED }

    /**
     * One sender of team messages (a robot, by its address).
     *
     * @param sender     host:port the messages came from
     * @param messages   counted messages
     * @param perMinute  over the last minute
     * @param oversize   messages over the size limit
     * @param largest    the largest message seen, bytes
     */
    public record Sender(String sender, long messages, double perMinute, long oversize, int largest) { }

    /**
     * What the guard knows now.
     *
     * @param profile             the rules in force
     * @param team                our team number
     * @param used                messages counted by the console this game
     * @param notCounted          messages heard outside READY, SET and PLAYING (or before a GameController was heard)
     * @param gameControllerHeard whether any GameController was heard (without one nothing counts)
     * @param left                messages left, or -1 when not known
     * @param leftFromGc          whether {@code left} is the GameController's own figure
     * @param perMinute           the team's rate over the last minute
     * @param secondsLeftInGame   game time left from the GameController, or -1 when none was heard
     * @param secondsToEmpty      at the current rate, or -1 when it does not run out (no rate, no limit)
     * @param verdict             the forecast in one word
     * @param oversize            messages over the size limit (each resets the score in HSL 2026)
     * @param lastOversize        "robot at 127.0.0.1:40001 sent 600 bytes (limit 512)", or null
     * @param senders             per sender, most messages first
     */
    public record Snapshot(RuleProfile profile, int team, long used, long notCounted, boolean gameControllerHeard,
                           long left, boolean leftFromGc, double perMinute,
                           long secondsLeftInGame, long secondsToEmpty, Verdict verdict, long oversize,
                           String lastOversize, List<Sender> senders) {

        /** One line for the status bar and {@code listen}. */
        public String describe() {
            String budget = left < 0 ? profile.teamMessageBudget().describe() : left + " left"
                    + (leftFromGc ? " (GameController)" : " (counted)");
            String line = String.format("team %d messages: %d used, %s, %.0f/min", team, used, budget, perMinute);
            line += switch (verdict) {
                case NO_LIMIT -> " · no budget in " + profile.name();
                case LIMIT_NOT_KNOWN -> " · " + profile.name() + ": budget not known";
                case WAITING_FOR_MESSAGES -> "";
                case ON_TRACK -> secondsLeftInGame < 0 ? " · lasts " + minutes(secondsToEmpty) + " at this rate"
                        : " · lasts the game at this rate";
                case RUNS_OUT_BEFORE_THE_END -> " · WARNING: runs out in " + minutes(secondsToEmpty) + ", "
                        + minutes(secondsLeftInGame) + " of the game left";
                case EXHAUSTED -> " · EXHAUSTED: a further message resets the score";
            };
            if (!gameControllerHeard && notCounted > 0) {
                line += " · " + notCounted + " heard, not counted: no GameController heard yet";
            }
            if (oversize > 0) {
                line += " · " + oversize + " over " + profile.maxTeamMessageBytes().value() + " bytes (last: "
                        + lastOversize + ")";
            }
            return line;
        }

        /**
         * The meter's short form, which never changes its shape: used, left and the forecast, e.g.
         * "3 used · 11997 left · lasts the game"; the rest (senders, rates, the rules) is in {@link #describe()}.
         */
        public String brief() {
            String budget = left < 0 ? "limit not known" : left + " left";
            String forecast = switch (verdict) {
                case NO_LIMIT -> "no budget";
                case LIMIT_NOT_KNOWN, WAITING_FOR_MESSAGES -> gameControllerHeard ? "no forecast yet" : "no GameController: not counting";
                case ON_TRACK -> secondsLeftInGame < 0 ? "lasts " + minutes(secondsToEmpty) : "lasts the game";
                case RUNS_OUT_BEFORE_THE_END -> "runs out in " + minutes(secondsToEmpty);
                case EXHAUSTED -> "EXHAUSTED";
            };
            return used + " used · " + budget + " · " + forecast + (oversize > 0 ? " · " + oversize + " OVERSIZE" : "");
        }

        private static String minutes(long seconds) {
            return seconds < 0 ? "?" : String.format("%d:%02d", seconds / 60, seconds % 60);
        }
    }

    private final MicrosClock clock;
    private final RuleProfile profile;
    private final int team;
    private final TimeBuckets teamRate = new TimeBuckets(WINDOW_MICROS, BUCKETS);
    private final Map<String, SenderCount> senders = new LinkedHashMap<>();
    private final KnownGameStateFormats formats = new KnownGameStateFormats();
    private long used;
    private long notCounted;
    private long oversize;
    private String lastOversize;
    private GameControlData game;
    private boolean gameCarriesBudget;

    public TeamMessageBudget(MicrosClock clock, RuleProfile profile, int team) {
        this.clock = clock;
        this.profile = profile;
        this.team = team;
    }

    public RuleProfile profile() {
        return profile;
    }

    public int team() {
        return team;
    }

    @Override
    public synchronized void accept(Envelope e) {
        // IN: the field's GameController; OUT: this console's own, when it referees the game
        if (e.channel() == Channel.GAMECONTROLLER && e.error() == null) {
            hearGameController(e.raw());
        } else if (e.channel() == Channel.TEAM_MESSAGE && e.direction() == Direction.IN) {
            count(e);
        }
    }

    private void hearGameController(byte[] raw) {
        Decoded<KnownGameStateFormats.Match> r = formats.recognise(raw);
        if (r.value() == null) {
            return;
        }
        game = r.value().data();
        // only the SPL and HSL formats carry a message budget; the others write zero there
        String kind = r.value().format().kind();
        gameCarriesBudget = kind.startsWith("gc.hsl") || kind.startsWith("gc.spl");
    }

    private void count(Envelope e) {
        long now = e.timeMicros();
        RuleLimit max = profile.maxTeamMessageBytes();
        SenderCount s = senders.computeIfAbsent(e.peer() == null ? "unknown" : e.peer().getHostString() + ":"
                + e.peer().getPort(), SenderCount::new);
        s.largest = Math.max(s.largest, e.size());
        if (max.known() && e.size() > max.value()) {
            oversize++;
            s.oversize++;
            lastOversize = "sender " + s.name + " sent " + e.size() + " bytes (limit " + max.value() + ")";
        }
        if (!counted()) {
            notCounted++;
            return;
        }
        used++;
        s.messages++;
        s.rate.add(now);
        teamRate.add(now);
    }

    /** The official GameController counts only in READY, SET and PLAYING, never in a shoot-out. */
    private boolean counted() {
        if (game == null) {
            return false; // no GameController heard: the state is not known, and INITIAL does not count
        }
        int state = game.state();
        return (state == GameControlData.STATE_READY || state == GameControlData.STATE_SET
                || state == GameControlData.STATE_PLAYING) && game.gamePhase() != GameControlData.GAME_PHASE_PENALTY_SHOOT_OUT;
    }

    public synchronized Snapshot snapshot() {
        long now = clock.nowMicros();
        double perSecond = teamRate.inWindow(now) / (WINDOW_MICROS / 1e6);
        long left = budgetLeft();
        long secondsLeftInGame = secondsLeftInGame();
        long toEmpty = left >= 0 && perSecond > 0 ? (long) Math.floor(left / perSecond) : -1;
        Verdict verdict = verdict(left, perSecond, toEmpty, secondsLeftInGame);
        List<Sender> rows = new ArrayList<>();
        for (SenderCount s : senders.values()) {
            rows.add(new Sender(s.name, s.messages, s.rate.inWindow(now), s.oversize, s.largest));
        }
        rows.sort(Comparator.comparingLong(Sender::messages).reversed());
        return new Snapshot(profile, team, used, notCounted, game != null, left, left >= 0 && gcBudget() >= 0, perSecond * 60,
                secondsLeftInGame, toEmpty, verdict, oversize, lastOversize, List.copyOf(rows));
    }

    private Verdict verdict(long left, double perSecond, long toEmpty, long secondsLeftInGame) {
        if (left < 0) {
            return profile.teamMessageBudget().kind() == RuleLimit.Kind.NONE ? Verdict.NO_LIMIT : Verdict.LIMIT_NOT_KNOWN;
        }
        if (left == 0) {
            return Verdict.EXHAUSTED;
        }
        if (perSecond <= 0) {
            return Verdict.WAITING_FOR_MESSAGES;
        }
        return secondsLeftInGame >= 0 && toEmpty < secondsLeftInGame * WARNING_MARGIN
                ? Verdict.RUNS_OUT_BEFORE_THE_END : Verdict.ON_TRACK;
    }

    /** The GameController's own count wins; else the profile's budget less what was counted; -1 unknown. */
    private long budgetLeft() {
        long gc = gcBudget();
        if (gc >= 0) {
            return gc;
        }
        RuleLimit budget = profile.teamMessageBudget();
        return budget.known() ? Math.max(0, budget.value() - used) : -1;
    }

    private long gcBudget() {
        if (game == null || !gameCarriesBudget) {
            return -1;
        }
        for (TeamInfo t : game.teams()) {
            if (t.teamNumber() == team) {
                return t.messageBudget();
            }
        }
        return -1;
    }

    /** The main clock of this half plus the halves still to come; -1 without a GameController. */
    private long secondsLeftInGame() {
        if (game == null) {
            return -1;
        }
        if (game.state() == GameControlData.STATE_FINISHED && !game.firstHalf()) {
            return 0;
        }
        long rest = Math.max(0, game.secsRemaining());
        if (game.firstHalf() && game.gamePhase() == GameControlData.GAME_PHASE_NORMAL) {
            rest += (long) profile.halfSeconds() * (profile.halves() - 1);
        }
        return rest;
    }

    /** One sender's counts; the per-minute rate uses the same one-minute window as the team's. */
    private static final class SenderCount {
        final String name;
        final TimeBuckets rate = new TimeBuckets(WINDOW_MICROS, BUCKETS);
        long messages;
        long oversize;
        int largest;

        SenderCount(String name) {
            this.name = name;
        }
    }
}
