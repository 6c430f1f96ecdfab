package touchline.protocol.gamecontroller;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;

/** Test data shared by the format tests: two teams with distinct values in player 1 and the last. */
final class Fixtures {

    private Fixtures() {
    }

    static ByteBuffer expected(int size) {
        ByteBuffer b = ByteBuffer.allocate(size).order(ByteOrder.LITTLE_ENDIAN);
        b.put(0, (byte) 'R').put(1, (byte) 'G').put(2, (byte) 'm').put(3, (byte) 'e');
        return b;
    }

    static List<RobotInfo> players(int count, RobotInfo first, RobotInfo last) {
        List<RobotInfo> list = new ArrayList<>();
        for (int i = 1; i <= count; i++) {
            list.add(i == 1 ? first : i == count ? last : RobotInfo.EMPTY);
        }
        return list;
    }

    static GameControlData game(int playersPerTeamSlots, int kickOffTeam, int secondaryState, int setPlayTeam,
                                int setPlayMode, boolean fullRobotInfo) {
        RobotInfo a1 = fullRobotInfo ? new RobotInfo(31, 17, 1, 2, 3, true) : RobotInfo.penalised(31, 17);
        RobotInfo aLast = fullRobotInfo ? new RobotInfo(14, 0, 4, 5, 6, false) : RobotInfo.penalised(14, 0);
        RobotInfo b1 = fullRobotInfo ? new RobotInfo(15, 0, 0, 1, 0, false) : RobotInfo.penalised(15, 0);
        RobotInfo bLast = fullRobotInfo ? new RobotInfo(34, 250, 0, 0, 1, true) : RobotInfo.penalised(34, 250);
        TeamInfo a = new TeamInfo(13, 1, 0, 3, 2, 0x0105, 0, 0, RobotInfo.EMPTY,
                players(playersPerTeamSlots, a1, aLast));
        TeamInfo b = new TeamInfo(200, 0, 0, 0, 1, 0x8001, 0, 0, RobotInfo.EMPTY,
                players(playersPerTeamSlots, b1, bLast));
        // legacy formats carry no gameType
        return new GameControlData(255, 4, fullRobotInfo ? 1 : 0, 0, 3, false, kickOffTeam, secondaryState, setPlayTeam, setPlayMode, 0,
                0xFFFF, -3, -5, List.of(a, b));
    }
}
