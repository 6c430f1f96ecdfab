package touchline.game;

import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.RobotInfo;
import touchline.protocol.gamecontroller.TeamInfo;

import java.util.ArrayList;
import java.util.List;

/**
 * The complete referee state of one game, in the manner of GameController3: actions check
 * legality against it and change it; timers are not stored as counters but derived from the
 * moments things began, so any clock reading gives exact {@code secsRemaining},
 * {@code secondaryTime} and {@code secsTillUnpenalised} (whole seconds, elapsed time floored
 * like the Java GameController). {@code teams[0]} is the left side as the operator sees it;
 * the teams swap sides at half time. Not thread-safe: {@link Game} serialises access.
 */
public final class GameState implements RefereeState {

    final LeagueParams params;
    PlayState state = PlayState.INITIAL;
    boolean firstHalf = true;
    /** Team number of the kicking team, or {@link GameControlData#DROP_BALL}. */
    int kickOffTeam;
    int firstHalfKickOffTeam;
    SecondaryState secondary = SecondaryState.NORMAL;
    int setPlayTeam;
    int setPlayMode;
    long setPlayModeSinceMs;
    int timeoutTeam;
    TeamState[] teams = new TeamState[2];
    long stateSinceMs;
    /** Whether the first kick-off of this half happened (the half clock runs only after it). */
    boolean halfStarted;
    long halfElapsedMs;
    long clockRunningSinceMs = -1;
    long blockSinceMs;
    int blockSeconds;

    GameState(LeagueParams params, int teamA, int colourA, int teamB, int colourB, long nowMs) {
        if (teamA == teamB) {
            throw new IllegalArgumentException("the two teams need different numbers");
        }
        this.params = params;
        teams[0] = new TeamState(teamA, colourA, params.playersPerTeam());
        teams[1] = new TeamState(teamB, colourB, params.playersPerTeam());
        kickOffTeam = teamA;
        firstHalfKickOffTeam = teamA;
        stateSinceMs = nowMs;
    }

    private GameState(GameState o) {
        params = o.params;
        state = o.state;
        firstHalf = o.firstHalf;
        kickOffTeam = o.kickOffTeam;
        firstHalfKickOffTeam = o.firstHalfKickOffTeam;
        secondary = o.secondary;
        setPlayTeam = o.setPlayTeam;
        setPlayMode = o.setPlayMode;
        setPlayModeSinceMs = o.setPlayModeSinceMs;
        timeoutTeam = o.timeoutTeam;
        teams = new TeamState[]{o.teams[0].copy(), o.teams[1].copy()};
        stateSinceMs = o.stateSinceMs;
        halfStarted = o.halfStarted;
        halfElapsedMs = o.halfElapsedMs;
        clockRunningSinceMs = o.clockRunningSinceMs;
        blockSinceMs = o.blockSinceMs;
        blockSeconds = o.blockSeconds;
    }

    /** A deep copy (for undo and for readers outside the game's lock). */
    public GameState copy() {
        return new GameState(this);
    }

    /**
     * A deep copy as the timer would leave it at {@code nowMs} (timed penalties ended, halves
     * switched, the half clock brought up to date); this state stays as it is (a reader's view of
     * a snapshot, such as the GameController's sender at its send instant).
     */
    public GameState at(long nowMs) {
        GameState c = copy();
        c.tick(nowMs);
        return c;
    }

    /** The timer's event at {@code nowMs}: {@link #advance}, then the half clock; true when the state changed. */
    boolean tick(long nowMs) {
        boolean changed = advance(nowMs);
        syncClock(nowMs);
        return changed;
    }

    /** {@code seconds} minus the whole seconds elapsed since {@code sinceMs} (may be negative). */
    static int remaining(int seconds, long sinceMs, long nowMs) {
        return seconds - (int) Math.floorDiv(nowMs - sinceMs, 1000L);
    }

    // ---- queries -------------------------------------------------------------------------

    public LeagueParams params() {
        return params;
    }

    public PlayState state() {
        return state;
    }

    @Override
    public boolean firstHalf() {
        return firstHalf;
    }

    public int kickOffTeam() {
        return kickOffTeam;
    }

    public boolean isPenaltyShootout() {
        return secondary == SecondaryState.PENALTYSHOOT;
    }

    public boolean isDropBall() {
        return kickOffTeam == GameControlData.DROP_BALL;
    }

    public SecondaryState secondary() {
        return secondary;
    }

    public int setPlayTeam() {
        return secondary.isSetPlay() ? setPlayTeam : 0;
    }

    public int setPlayMode() {
        return secondary.isSetPlay() ? setPlayMode : 0;
    }

    public int timeoutTeam() {
        return secondary == SecondaryState.TIMEOUT ? timeoutTeam : 0;
    }

    /** Team on side 0 (left) or 1 (right). */
    public TeamState teamOnSide(int side) {
        return teams[side];
    }

    /** The team with this number, or null. */
    public TeamState team(int number) {
        for (TeamState t : teams) {
            if (t.number == number) {
                return t;
            }
        }
        return null;
    }

    public TeamState otherTeam(int number) {
        return teams[0].number == number ? teams[1] : teams[0];
    }

    public boolean isClockRunning() {
        return clockRunningSinceMs >= 0;
    }

    public int secsRemaining(long nowMs) {
        long elapsed = halfElapsedMs + (isClockRunning() ? nowMs - clockRunningSinceMs : 0);
        return params.halfSeconds() - (int) Math.floorDiv(elapsed, 1000L);
    }

    public int secondaryTime(long nowMs) {
        switch (state) {
            case INITIAL:
                if (secondary == SecondaryState.PENALTYSHOOT) {
                    return 0;
                }
                if (secondary == SecondaryState.TIMEOUT) {
                    return remaining(params.timeoutSeconds(), stateSinceMs, nowMs);
                }
                // The half-time break counts down in the second half's INITIAL, and below zero after.
                return firstHalf ? 0 : remaining(params.halfTimePauseSeconds(), stateSinceMs, nowMs);
            case READY:
                return Math.max(0, remaining(params.readySeconds(), stateSinceMs, nowMs));
            case PLAYING:
                if (secondary == SecondaryState.PENALTYSHOOT) {
                    return Math.max(0, remaining(params.penaltyShotSeconds(), stateSinceMs, nowMs));
                }
                if (secondary.isSetPlay()) {
                    return setPlayMode == 1
                            ? Math.max(0, remaining(params.setPlayPrepareSeconds(), setPlayModeSinceMs, nowMs)) : 0;
                }
                return blockSeconds > 0 ? Math.max(0, remaining(blockSeconds, blockSinceMs, nowMs)) : 0;
            default:
                return 0;
        }
    }

    // ---- what the actions every league shares ask (RefereeState) -------------------------

    @Override
    public boolean playing() {
        return state == PlayState.PLAYING;
    }

    @Override
    public boolean inShootout() {
        return isPenaltyShootout();
    }

    @Override
    public int kickingTeam() {
        return kickOffTeam;
    }

    @Override
    public boolean finished() {
        return state == PlayState.FINISHED;
    }

    @Override
    public int gameKickOffTeam() {
        return firstHalfKickOffTeam;
    }

    /** None: the HL GameController ends no game early. */
    @Override
    public int mercyGoals() {
        return 0;
    }

    @Override
    public void countGoal(int team) {
        team(team).score++;
    }

    /** The shot over: FINISHED (the next one begins with {@code ToSet}). */
    @Override
    public void shotScored(int team, long nowMs) {
        TeamState t = team(team);
        t.singleShots |= 1 << (t.penaltyShot - 1);
        enter(PlayState.FINISHED, nowMs);
    }

    @Override
    public void endGame(long nowMs) {
        firstHalf = false;
        enter(PlayState.FINISHED, nowMs);
    }

    /** Secondary state PENALTYSHOOT, the clock restarted and penalties lifted; each kick is SET, PLAYING, FINISHED. */
    @Override
    public void beginShootout(int first, long nowMs) {
        secondary = SecondaryState.PENALTYSHOOT;
        kickOffTeam = first;
        for (TeamState t : teams) {
            t.penaltyShot = 0;
            t.singleShots = 0;
        }
        restartClock(nowMs);
    }

    /** READY with the ready countdown, any set play over, no ball-free countdown. */
    @Override
    public void readyForKickOff(int team, long nowMs) {
        kickOffTeam = team;
        endSetPlay();
        block(0, nowMs);
        enter(PlayState.READY, nowMs);
    }

    // ---- changes shared by actions -----------------------------------------------------

    void enter(PlayState next, long nowMs) {
        state = next;
        stateSinceMs = nowMs;
    }

    void endSetPlay() {
        secondary = SecondaryState.NORMAL;
        setPlayTeam = 0;
        setPlayMode = 0;
    }

    void block(int seconds, long nowMs) {
        blockSeconds = seconds;
        blockSinceMs = nowMs;
    }

    /** Starts or stops the half clock so that it runs exactly when the rules say it does. */
    void syncClock(long nowMs) {
        boolean run = halfStarted
                && (state == PlayState.READY || state == PlayState.SET || state == PlayState.PLAYING)
                && !secondary.isSetPlay() && secondary != SecondaryState.TIMEOUT;
        if (run && !isClockRunning()) {
            clockRunningSinceMs = nowMs;
        } else if (!run && isClockRunning()) {
            halfElapsedMs += nowMs - clockRunningSinceMs;
            clockRunningSinceMs = -1;
        }
    }

    /**
     * Changes that happen by themselves as time passes: timed penalties end, and a finished
     * first half turns into the second half (teams swap sides, the other team kicks off).
     *
     * @return whether anything changed
     */
    boolean advance(long nowMs) {
        boolean changed = false;
        for (TeamState t : teams) {
            for (PlayerState p : t.players) {
                if (p.penalty.timed() && remaining(p.penaltySeconds, p.penaltySinceMs, nowMs) <= 0) {
                    p.unpenalise();
                    changed = true;
                }
            }
        }
        if (state == PlayState.FINISHED && firstHalf) {
            startSecondHalf(nowMs);
            changed = true;
        }
        return changed;
    }

    private void startSecondHalf(long nowMs) {
        firstHalf = false;
        teams = new TeamState[]{teams[1], teams[0]};
        kickOffTeam = otherTeam(firstHalfKickOffTeam).number;
        endSetPlay();
        restartClock(nowMs);
    }

    /** A new period (second half, penalty shoot-out): INITIAL, clock reset, penalties lifted. */
    void restartClock(long nowMs) {
        enter(PlayState.INITIAL, nowMs);
        halfStarted = false;
        halfElapsedMs = 0;
        clockRunningSinceMs = -1;
        blockSeconds = 0;
        for (TeamState t : teams) {
            for (PlayerState p : t.players) {
                if (p.isPenalised()) {
                    p.unpenalise();
                }
            }
        }
    }

    // ---- wire view -----------------------------------------------------------------------

    /** The packet content at {@code nowMs} (packetNumber 0; the sender numbers packets). */
    public GameControlData toControlData(long nowMs) {
        List<TeamInfo> wireTeams = new ArrayList<>(2);
        for (TeamState t : teams) {
            List<RobotInfo> players = new ArrayList<>(LeagueParams.MAX_PLAYERS);
            for (PlayerState p : t.players) {
                players.add(new RobotInfo(p.penalty.code(), p.secsTillUnpenalised(nowMs), p.warnings, p.yellowCards,
                        p.redCards, p.goalkeeper));
            }
            wireTeams.add(new TeamInfo(t.number, t.colour, 0, t.score, t.penaltyShot, t.singleShots, 0, 0,
                    RobotInfo.EMPTY, players));
        }
        return new GameControlData(0, params.playersPerTeam(), params.gameType(), 0, state.code(), firstHalf,
                kickOffTeam, secondary.code(), setPlayTeam(), setPlayMode(), 0, 0xFFFF, secsRemaining(nowMs),
                secondaryTime(nowMs), wireTeams);
    }

    /** One line such as {@code PLAYING 1st half, 512 s left, ..., kick-off 7, 13 1:0 7} at {@code now}. */
    public String describe(long now) {
        GameState s = this;
        StringBuilder b = new StringBuilder(s.state.name());
        if (s.secondary != SecondaryState.NORMAL) {
            b.append('/').append(s.secondary.name());
            if (s.secondary.isSetPlay()) {
                b.append(" team ").append(s.setPlayTeam).append(" mode ").append(s.setPlayMode);
            }
        }
        b.append(s.firstHalf ? " 1st half" : " 2nd half");
        b.append(", ").append(s.secsRemaining(now)).append(" s left");
        b.append(", secondary ").append(s.secondaryTime(now)).append(" s");
        b.append(", kick-off ").append(s.isDropBall() ? "dropped ball" : String.valueOf(s.kickOffTeam));
        b.append(", ").append(s.teams[0].number).append(' ').append(s.teams[0].score).append(':')
                .append(s.teams[1].score).append(' ').append(s.teams[1].number);
        return b.toString();
    }
}
