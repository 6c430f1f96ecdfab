package touchline.protocol.gamecontroller;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Writing the console's neutral game state as HSL: fields at their offsets, a set play and
 * the game phase side by side, and penalties of the other leagues mapped to their nearest HSL
 * rule (never to "unpenalised").
 */
class HslEncodingTest {

    private static TeamInfo team(int number, int... penalties) {
        List<RobotInfo> players = new ArrayList<>();
        for (int p = 0; p < 20; p++) {
            players.add(new RobotInfo(p < penalties.length ? penalties[p] : 0, p == 0 ? 7 : 0, 0, p == 1 ? 1 : 0, 0,
                    p == 2));
        }
        return new TeamInfo(number, 1, 7, 2, 0, 0, 0, 11999, RobotInfo.EMPTY, players);
    }

    private static GameControlData penaltyKickInExtraTime(TeamInfo a, TeamInfo b) {
        return new GameControlData(42, 5, 0, 2, GameControlData.STATE_PLAYING, true, 14, 6, 14, 0, 0, 0, -3, 50,
                List.of(a, b), 2, true);
    }

    @Test
    void everyFieldIsWrittenAtItsOffset() {
        byte[] v20 = new HslGameState20().encode(penaltyKickInExtraTime(team(5), team(14)));
        assertEquals(158, v20.length);
        assertEquals(42, v20[5]);
        assertEquals(5, v20[6]);
        assertEquals(2, v20[7], "competitionType LARGE");
        assertEquals(1, v20[8], "stopped");
        assertEquals(2, v20[9], "gamePhase EXTRA_TIME beside the set play");
        assertEquals(3, v20[10], "PLAYING");
        assertEquals(3, v20[11], "PENALTY_KICK");
        assertEquals(14, v20[13]);
        assertEquals(-3, (short) ((v20[14] & 0xFF) | v20[15] << 8));
        assertEquals(3, v20[18 + 3], "goalkeeper number");
        assertEquals(7, v20[18 + 10 + 1], "player 1 secsTillUnpenalised");
        assertEquals(1, v20[18 + 10 + 3 + 2], "player 2 cautions");
        GameControlData back = new HslGameState20().decode(v20).value();
        assertEquals(2, back.gamePhase());
        assertEquals(6, back.secondaryState());
        assertTrue(back.stopped());
    }

    @Test
    void humanoidLeaguePenaltiesBecomeTheirNearestHslRule() {
        // physical contact, ball manipulation, illegal attack, illegal defence, pickup/incapable, service, manual,
        // substitute, HSL motion in stop, HSL cautioned
        TeamInfo hl = team(5, 31, 30, 32, 33, 34, 35, 15, 14, 43, 51);
        byte[] v20 = new HslGameState20().encode(penaltyKickInExtraTime(hl, team(14)));
        byte[] v19 = new HslGameState19().encode(penaltyKickInExtraTime(hl, team(14)));
        int[] expected20 = {10, 9, 1, 1, 6, 5, 6, 13, 3, 11};
        int[] expected19 = {9, 8, 1, 1, 5, 4, 5, 11, 5, 5};
        for (int p = 0; p < expected20.length; p++) {
            assertEquals(expected20[p], v20[18 + 10 + 3 * p], "v20 player " + (p + 1));
            assertEquals(expected19[p], v19[18 + 10 + 4 * p], "v19 player " + (p + 1));
        }
    }

    @Test
    void aDroppedBallHasNoKickingTeam() {
        GameControlData d = new GameControlData(0, 5, 0, 1, GameControlData.STATE_READY, false,
                GameControlData.DROP_BALL, 0, 0, 0, 0, 0, 570, 45, List.of(team(14), team(5)));
        byte[] v20 = new HslGameState20().encode(d);
        assertEquals(-1, v20[13], "255");
        assertEquals(0, v20[8], "an older format's state is never stopped");
        assertEquals(GameControlData.DROP_BALL, new HslGameState20().decode(v20).value().kickOffTeam());
    }
}
