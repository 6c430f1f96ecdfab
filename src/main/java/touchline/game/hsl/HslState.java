package touchline.game.hsl;

import touchline.game.RefereeState;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.RobotInfo;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.protocol.gamecontroller.TeamInfo;

import java.util.ArrayList;
import java.util.List;

/**
 * The referee state of one HSL game as the official GameController 7.0.0 / 6.0.1 keeps it.
 * Timers are remaining durations that run while their condition holds ({@link #advance}
 * moves time forward event by event, so a timer that ends changes the state at the exact
 * instant it ends). While robots still see the state from before a PLAYING whistle, that
 * copy is {@link #delayed}; its timers run by its own state. {@code teams[0]} defends the left goal as the operator sees
 * it; the teams swap at half time. Not thread-safe: {@link HslGame} serialises access.
 * Over 400 lines because its timers (game clock, shot, secondary time, players' penalties),
 * which of them run in which state, the next expiry among them and what an expiry changes are
 * one rule of the official GameController: split apart, each part would ask the others the state.
 * It also answers the actions every league shares ({@link RefereeState}, some 80 lines): what a
 * goal, the mercy rule and a shoot-out change here touches the same timers.
 */
public final class HslState implements RefereeState {

    /** {@link #kickingTeam} when no team kicks (dropped ball, FINISHED, open play). */
    public static final int NO_TEAM = -1;

    final HslRules rules;
    HslPhase phase = HslPhase.NORMAL;
    HslPlayState state = HslPlayState.INITIAL;
    boolean stopped;
    boolean firstHalf = true;
    SetPlay setPlay;
    int kickingTeam;
    int firstKickOffTeam;
    HslTeam[] teams;
    /** Main clock (can go negative). */
    long clockMs;
    /** Whether this half's first kick-off was whistled (before it the clock stands in READY/SET). */
    boolean halfKickedOff;
    /** The main clock when the current stoppage (goal, dropped ball, penalty kick) began; -1 none. */
    long stoppageClockMs = -1;
    long addedMs;
    SecondaryTimer secondary = SecondaryTimer.NONE;
    long secondaryMs;
    /** Time until the second half begins by itself; -1 when not pending. */
    long switchHalfMs = -1;
    /** What robots see while the state before a PLAYING whistle is held for them; null otherwise. */
    HslState delayed;
    long delayMs;
    long lastMs;

    HslState(HslRules rules, int leftTeam, TeamColour[] leftColours, int rightTeam, TeamColour[] rightColours,
             long nowMs) {
        if (leftTeam == rightTeam) {
            throw new IllegalArgumentException("the two teams need different numbers");
        }
        String bad = HslGame.colourConflict(leftColours, rightColours);
        if (bad != null) {
            throw new IllegalArgumentException(bad);
        }
        this.rules = rules;
        teams = new HslTeam[]{new HslTeam(leftTeam, leftColours[0], leftColours[1], rules),
                new HslTeam(rightTeam, rightColours[0], rightColours[1], rules)};
        kickingTeam = leftTeam;
        firstKickOffTeam = leftTeam;
        clockMs = rules.halfMs();
        lastMs = nowMs;
    }

    private HslState(HslState o, boolean withDelay) {
        rules = o.rules;
        phase = o.phase;
        state = o.state;
        stopped = o.stopped;
        firstHalf = o.firstHalf;
        setPlay = o.setPlay;
        kickingTeam = o.kickingTeam;
        firstKickOffTeam = o.firstKickOffTeam;
        teams = new HslTeam[]{o.teams[0].copy(), o.teams[1].copy()};
        clockMs = o.clockMs;
        halfKickedOff = o.halfKickedOff;
        stoppageClockMs = o.stoppageClockMs;
        addedMs = o.addedMs;
        secondary = o.secondary;
        secondaryMs = o.secondaryMs;
        switchHalfMs = o.switchHalfMs;
        delayed = withDelay && o.delayed != null ? o.delayed.copy() : null;
        delayMs = withDelay ? o.delayMs : 0;
        lastMs = o.lastMs;
    }

    /** A deep copy (undo, readers outside the game's lock). */
    public HslState copy() {
        return new HslState(this, true);
    }

    /** A deep copy with time run on to {@code nowMs}; this state stays as it is (a reader's view of a snapshot). */
    public HslState at(long nowMs) {
        HslState c = copy();
        c.advance(nowMs);
        return c;
    }

    /** Whole seconds rounded up, as the official GameController sends every timer. */
    static long ceilSeconds(long ms) {
        return -Math.floorDiv(-ms, 1000L);
    }

    // ---- queries -------------------------------------------------------------------------

    public HslRules rules() {
        return rules;
    }

    public HslPlayState state() {
        return state;
    }

    public HslPhase phase() {
        return phase;
    }

    public boolean stopped() {
        return stopped;
    }

    @Override
    public boolean firstHalf() {
        return firstHalf;
    }

    /** The running set play (a kick-off included), or null. */
    public SetPlay setPlay() {
        return setPlay;
    }

    /** Team number of the kicking team, or {@link #NO_TEAM}. */
    @Override
    public int kickingTeam() {
        return kickingTeam;
    }

    /** Whether robots are still shown the state from before the last PLAYING whistle. */
    public boolean delaying() {
        return delayed != null;
    }

    public HslTeam teamOnSide(int side) {
        return teams[side];
    }

    /** The team with this number, or null. */
    public HslTeam team(int number) {
        for (HslTeam t : teams) {
            if (t.number == number) {
                return t;
            }
        }
        return null;
    }

    public HslTeam otherTeam(int number) {
        return teams[0].number == number ? teams[1] : teams[0];
    }

    public int secsRemaining() {
        return (int) ceilSeconds(clockMs);
    }

    public int secondaryTime() {
        if (secondary == SecondaryTimer.NONE) {
            return 0;
        }
        long secs = ceilSeconds(secondaryMs);
        return (int) (secondary.expires ? Math.max(0, secs) : secs);
    }

    // ---- running time --------------------------------------------------------------------

    private boolean clockRuns() {
        if (phase == HslPhase.PENALTY_SHOOT_OUT) {
            return state == HslPlayState.PLAYING; // the shot's own time
        }
        if (stopped && !rules.clockRunsWhileStopped()) {
            return false;
        }
        return state == HslPlayState.PLAYING
                || (halfKickedOff && (state == HslPlayState.READY || state == HslPlayState.SET));
    }

    /** A penalty shoot-out shot is being taken: its time ends it. */
    private boolean shotRuns() {
        return phase == HslPhase.PENALTY_SHOOT_OUT && state == HslPlayState.PLAYING;
    }

    private boolean secondaryRuns() {
        return switch (secondary) {
            case NONE -> false;
            case READY -> state == HslPlayState.READY && !stopped;
            case SET_PLAY -> state == HslPlayState.PLAYING && !stopped;
            case TIMEOUT, HALF_TIME_BREAK -> true;
        };
    }

    private boolean penaltiesRun() {
        return (state == HslPlayState.READY || state == HslPlayState.PLAYING) && !stopped;
    }

    /** Time to the next timer that ends something, or Long.MAX_VALUE. */
    private long nextExpiry() {
        long next = Long.MAX_VALUE;
        if (secondary.expires && secondaryRuns() && secondaryMs > 0) {
            next = secondaryMs;
        }
        if (switchHalfMs > 0) {
            next = Math.min(next, switchHalfMs);
        }
        if (shotRuns() && clockMs > 0) {
            next = Math.min(next, clockMs);
        }
        if (delayed != null && delayMs > 0) {
            next = Math.min(next, Math.min(delayMs, delayed.nextExpiry()));
        }
        if (penaltiesRun()) {
            for (HslTeam t : teams) {
                for (HslPlayer p : t.players) {
                    if (p.isPenalised() && p.timerStarted && p.penaltyMs > 0) {
                        next = Math.min(next, p.penaltyMs);
                    }
                }
            }
        }
        return next;
    }

    /**
     * Lets time pass up to {@code nowMs}, stopping at every instant a timer ends to apply what
     * it ends (READY to SET, a set play over, motion in set served, the second half begins, the
     * robots' delay over).
     *
     * @return whether anything but the clocks changed
     */
    boolean advance(long nowMs) {
        boolean changed = false;
        while (nowMs > lastMs) {
            long step = Math.min(nowMs - lastMs, nextExpiry());
            changed |= elapse(step);
            lastMs += step;
        }
        return changed;
    }

    private boolean elapse(long ms) {
        boolean clock = clockRuns();
        boolean secondaryRunning = secondaryRuns();
        boolean penalties = penaltiesRun();
        boolean changed = false;
        boolean shot = shotRuns();
        if (clock) {
            clockMs -= ms;
            if (shot && clockMs <= 0) {
                clockMs = 0;
                endShot();
                changed = true;
            }
        }
        if (delayed != null) {
            // the held copy is not frozen: its clocks run as its own state says (SET after a kick-off: the clock runs)
            delayed.elapse(ms);
            delayed.lastMs += ms;
            delayMs -= ms;
            if (delayMs <= 0) {
                delayed = null;
                changed = true;
            }
        }
        if (penalties) {
            for (HslTeam t : teams) {
                for (HslPlayer p : t.players) {
                    if (p.isPenalised() && p.timerStarted && p.penaltyMs > 0) {
                        p.penaltyMs -= ms;
                        if (p.penaltyMs <= 0) {
                            p.penaltyMs = 0;
                            if (p.penalty == HslPenalty.MOTION_IN_SET) {
                                p.unpenalise();
                            }
                            changed = true;
                        }
                    }
                }
            }
        }
        if (secondaryRunning) {
            boolean wasPositive = secondaryMs > 0;
            secondaryMs -= ms;
            if (secondary.expires && wasPositive && secondaryMs <= 0) {
                secondaryEnded();
                changed = true;
            }
        }
        if (switchHalfMs > 0) {
            switchHalfMs -= ms;
            if (switchHalfMs <= 0) {
                switchHalf();
                changed = true;
            }
        }
        return changed;
    }

    private void secondaryEnded() {
        if (secondary == SecondaryTimer.READY) {
            enterSet();
        } else if (secondary == SecondaryTimer.SET_PLAY) {
            endSetPlay();
        }
    }

    // ---- what the actions every league shares ask (RefereeState) -------------------------

    @Override
    public boolean playing() {
        return state == HslPlayState.PLAYING;
    }

    @Override
    public boolean inShootout() {
        return phase == HslPhase.PENALTY_SHOOT_OUT;
    }

    @Override
    public boolean finished() {
        return state == HslPlayState.FINISHED;
    }

    @Override
    public int gameKickOffTeam() {
        return firstKickOffTeam;
    }

    @Override
    public int mercyGoals() {
        return rules.mercyGoals();
    }

    /** Not for a team marked for illegal communication. */
    @Override
    public void countGoal(int team) {
        HslTeam t = team(team);
        t.score += t.illegalCommunication ? 0 : 1;
    }

    @Override
    public void shotScored(int team, long nowMs) {
        HslTeam t = team(team);
        t.singleShots |= 1 << (t.penaltyShot - 1);
        endShot();
    }

    @Override
    public void endGame(long nowMs) {
        firstHalf = false;
        finish();
    }

    /**
     * As the official GameController: the shot's clock set, every player off as a substitute and no
     * goalkeeper until each team selects its player ({@link SelectShooter}).
     */
    @Override
    public void beginShootout(int first, long nowMs) {
        phase = HslPhase.PENALTY_SHOOT_OUT;
        state = HslPlayState.INITIAL;
        kickingTeam = first;
        clockMs = rules.penaltyShotMs();
        switchHalfMs = -1;
        startSecondary(SecondaryTimer.NONE, 0);
        for (HslTeam t : teams) {
            t.goalkeeper = 0;
            t.penaltyShot = 0;
            t.singleShots = 0;
            for (HslPlayer p : t.players) {
                p.penalise(HslPenalty.SUBSTITUTE, 0, false);
            }
        }
    }

    /** READY after a stoppage (a timeout gives the time since back). */
    @Override
    public void readyForKickOff(int team, long nowMs) {
        beginStoppage();
        enterReady(SetPlay.KICK_OFF, team);
    }

    // ---- changes shared by actions -----------------------------------------------------

    void startSecondary(SecondaryTimer kind, long ms) {
        secondary = kind;
        secondaryMs = ms;
    }

    void enterReady(SetPlay kind, int kicking) {
        state = HslPlayState.READY;
        setPlay = kind;
        kickingTeam = kicking;
        stopped = false;
        startSecondary(SecondaryTimer.READY, rules.readyMs());
    }

    void enterSet() {
        state = HslPlayState.SET;
        startSecondary(SecondaryTimer.NONE, 0);
    }

    void endSetPlay() {
        setPlay = null;
        kickingTeam = NO_TEAM;
        startSecondary(SecondaryTimer.NONE, 0);
    }

    /** Remembers the clock when play stops for a restart, so that a timeout can give the time back. */
    void beginStoppage() {
        stoppageClockMs = clockMs;
    }

    /** Holds the current state for the robots for the rules' delay (a PLAYING whistle). */
    void holdForRobots() {
        if (rules.delayAfterPlayingMs() > 0) {
            delayed = new HslState(this, false);
            delayMs = rules.delayAfterPlayingMs();
        }
    }

    void finish() {
        state = HslPlayState.FINISHED;
        setPlay = null;
        kickingTeam = NO_TEAM;
        stopped = false;
        stoppageClockMs = -1;
        startSecondary(SecondaryTimer.NONE, 0);
    }

    /** A shoot-out shot is over (goal, miss or time): FINISHED, the other team shoots next. */
    void endShot() {
        state = HslPlayState.FINISHED;
        kickingTeam = otherTeam(kickingTeam).number;
    }

    /** The first half is over: INITIAL of the second, sides swapped, the other team kicks off. */
    void switchHalf() {
        firstHalf = false;
        switchHalfMs = -1;
        teams = new HslTeam[]{teams[1], teams[0]};
        kickingTeam = otherTeam(firstKickOffTeam).number;
        state = HslPlayState.INITIAL;
        setPlay = null;
        stopped = false;
        clockMs = phase == HslPhase.EXTRA_TIME ? rules.extraHalfMs() : rules.halfMs();
        addedMs = 0;
        halfKickedOff = false;
        stoppageClockMs = -1;
        for (HslTeam t : teams) {
            for (HslPlayer p : t.players) {
                if (p.isPenalised() && !p.permanent()) {
                    p.unpenalise();
                }
            }
        }
    }

    /** Milliseconds of this half played so far (with added time). */
    long playedMs() {
        long half = phase == HslPhase.EXTRA_TIME ? rules.extraHalfMs() : rules.halfMs();
        return half + addedMs - clockMs;
    }

    // ---- wire view -----------------------------------------------------------------------

    /** What robots get: the held state during the delay after a PLAYING whistle, else the true one. */
    public GameControlData robotData() {
        return (delayed != null ? delayed : this).trueData();
    }

    /** The true state (the monitors' "RGTD" copy), packetNumber 0. */
    public GameControlData trueData() {
        List<TeamInfo> wireTeams = new ArrayList<>(2);
        for (HslTeam t : teams) {
            List<RobotInfo> players = new ArrayList<>(HslRules.MAX_PLAYERS);
            for (int n = 1; n <= HslRules.MAX_PLAYERS; n++) {
                HslPlayer p = t.player(n);
                players.add(new RobotInfo(p.penalty.neutral(), p.secsTillUnpenalised(), p.warnings, p.cautions, 0,
                        n == t.goalkeeper));
            }
            wireTeams.add(new TeamInfo(t.number, t.fieldColour.ordinal(), t.goalkeeperColour.ordinal(), t.score,
                    t.penaltyShot, t.singleShots, 0, t.messageBudget, RobotInfo.EMPTY, players));
        }
        int gamePhase = state == HslPlayState.TIMEOUT ? 3 : phase.wire();
        boolean wireSetPlay = setPlay != null && setPlay != SetPlay.KICK_OFF;
        int kicking = kickingTeam == NO_TEAM ? GameControlData.DROP_BALL : kickingTeam;
        return new GameControlData(0, rules.competition().playersPerTeam(), 0, rules.competition().type(),
                state.wire(), firstHalf && (phase != HslPhase.EXTRA_TIME || rules.firstHalfInExtraTime()), kicking, wireSetPlay ? setPlay.wire().secondaryState() : gamePhase,
                wireSetPlay ? kicking : 0, 0, 0, 0, secsRemaining(), secondaryTime(), wireTeams, gamePhase, stopped);
    }

    /** One line for logs, the CLI and the referee box: state, phase, clocks, score, budgets. */
    public String describe() {
        HslState s = this;
        StringBuilder b = new StringBuilder(s.state.name());
        if (s.phase != HslPhase.NORMAL) {
            b.append('/').append(s.phase.name());
        }
        if (s.stopped) {
            b.append(" STOPPED");
        }
        if (s.setPlay != null) {
            b.append(' ').append(s.setPlay.label());
        }
        b.append(s.firstHalf ? " 1st half" : " 2nd half");
        b.append(", ").append(s.secsRemaining()).append(" s left");
        b.append(", secondary ").append(s.secondaryTime()).append(" s");
        b.append(", kicking ").append(s.kickingTeam == HslState.NO_TEAM ? "none" : String.valueOf(s.kickingTeam));
        HslTeam l = s.teams[0];
        HslTeam r = s.teams[1];
        b.append(", ").append(l.number).append(' ').append(l.score).append(':').append(r.score).append(' ')
                .append(r.number);
        b.append(", budget ").append(l.messageBudget).append('/').append(r.messageBudget);
        if (s.delayed != null) {
            b.append(", robots still see SET");
        }
        return b.toString();
    }
}
