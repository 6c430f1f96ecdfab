package touchline.protocol.gamecontroller;

import java.util.List;

/**
 * The content of one game-state ("RGme") datagram in format-neutral form, in the code space of
 * the Humanoid League v12 packet (the default format). Serializers for other versions translate
 * states, set plays, kick-off sentinel and penalties to their own encoding; fields a format
 * lacks are dropped on encode and come back as defaults on decode.
 *
 * @param packetNumber       wrapping packet counter (0..255)
 * @param playersPerTeam     players on the field per team
 * @param gameType           HL byte 8 (round robin / playoff / drop-in); SPL competitionPhase
 * @param competitionType    SPL competitionType (0 normal, 1 most passes); HSL division (0 SMALL 1 MIDDLE 2 LARGE)
 * @param state              0 INITIAL 1 READY 2 SET 3 PLAYING 4 FINISHED (5 STANDBY, SPL)
 * @param firstHalf          whether the first half is being played
 * @param kickOffTeam        team number of the kicking team, or {@link #DROP_BALL}
 * @param secondaryState     HL STATE2_* code: 0 NORMAL 1 PENALTYSHOOT 2 OVERTIME 3 TIMEOUT
 *                           4 DIRECT_FREEKICK 5 INDIRECT_FREEKICK 6 PENALTYKICK 7 CORNER_KICK
 *                           8 GOAL_KICK 9 THROW_IN
 * @param setPlayTeam        secondaryStateInfo[0]: team number executing the set play
 * @param setPlayMode        secondaryStateInfo[1]: 0 stay still, 1 may position, 2 prepare
 * @param dropInTeam         legacy drop-in team byte
 * @param dropInTime         legacy drop-in time (0xFFFF = none yet)
 * @param secsRemaining      seconds left in the half (signed)
 * @param secondaryTime      secondary countdown (signed)
 * @param teams              exactly two teams, in wire order
 * @param gamePhase          0 NORMAL 1 PENALTY_SHOOT_OUT 2 OVERTIME / EXTRA_TIME 3 TIMEOUT; SPL and HSL send it
 *                           beside the set play (a penalty kick in extra time), HL folds both into
 *                           {@code secondaryState}, where a running set play wins
 * @param stopped            HSL (2026): play is stopped ("Stop Play", or a set play without READY being
 *                           prepared); robots must stand still
 */
public record GameControlData(int packetNumber, int playersPerTeam, int gameType, int competitionType, int state,
                              boolean firstHalf, int kickOffTeam, int secondaryState, int setPlayTeam,
                              int setPlayMode, int dropInTeam, int dropInTime, int secsRemaining,
                              int secondaryTime, List<TeamInfo> teams, int gamePhase, boolean stopped) {

    /** Neutral marker for "dropped ball, no kicking team" (wire: 0x80 / 255 / 2 by format). */
    public static final int DROP_BALL = -1;

    public static final int STATE_INITIAL = 0;
    public static final int STATE_READY = 1;
    public static final int STATE_SET = 2;
    public static final int STATE_PLAYING = 3;
    public static final int STATE_FINISHED = 4;
    /** SPL only: between halves and before the game, robots stand still. */
    public static final int STATE_STANDBY = 5;

    public static final int GAME_PHASE_NORMAL = 0;
    public static final int GAME_PHASE_PENALTY_SHOOT_OUT = 1;

    public GameControlData {
        teams = List.copyOf(teams);
        if (teams.size() != 2) {
            throw new IllegalArgumentException("a game has two teams, got " + teams.size());
        }
    }

    /**
     * The content of a format without a separate game phase and without {@code stopped}: the
     * phase is the secondary state when that is one (1–3), else NORMAL.
     */
    public GameControlData(int packetNumber, int playersPerTeam, int gameType, int competitionType, int state,
                           boolean firstHalf, int kickOffTeam, int secondaryState, int setPlayTeam,
                           int setPlayMode, int dropInTeam, int dropInTime, int secsRemaining,
                           int secondaryTime, List<TeamInfo> teams) {
        this(packetNumber, playersPerTeam, gameType, competitionType, state, firstHalf, kickOffTeam, secondaryState,
                setPlayTeam, setPlayMode, dropInTeam, dropInTime, secsRemaining, secondaryTime, teams,
                secondaryState >= 1 && secondaryState <= 3 ? secondaryState : 0, false);
    }

    public GameControlData withPacketNumber(int number) {
        return new GameControlData(number & 0xFF, playersPerTeam, gameType, competitionType, state, firstHalf,
                kickOffTeam, secondaryState, setPlayTeam, setPlayMode, dropInTeam, dropInTime, secsRemaining,
                secondaryTime, teams, gamePhase, stopped);
    }

    /** The team with this number, or null. */
    public TeamInfo team(int teamNumber) {
        for (TeamInfo t : teams) {
            if (t.teamNumber() == teamNumber) {
                return t;
            }
        }
        return null;
    }

    /**
     * The one source of the game-state names (the GameController's own words, also what robots
     * report in their Status): {@code INITIAL}, {@code READY}, ... or {@code STATE}n for a code
     * without a name.
     */
    public static String stateName(int state) {
        return state >= 0 && state < STATE_NAMES.size() ? STATE_NAMES.get(state) : "STATE" + state;
    }

    /** The code of a state name ({@link #stateName} read back), -1 for a name that is not one. */
    public static int stateCode(String name) {
        return name == null ? -1 : STATE_NAMES.indexOf(name);
    }

    /** READY, SET and PLAYING: the states in which robots are on the field and play. */
    public static boolean isPlay(int state) {
        return state >= STATE_READY && state <= STATE_PLAYING;
    }

    private static final List<String> STATE_NAMES = List.of("INITIAL", "READY", "SET", "PLAYING", "FINISHED", "STANDBY");
}
