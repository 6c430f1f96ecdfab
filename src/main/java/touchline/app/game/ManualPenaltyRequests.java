package touchline.app.game;

import touchline.game.Action;
import touchline.game.Penalty;
import touchline.game.Penalize;
import touchline.game.SetGoalkeeper;
import touchline.game.Unpenalize;
import touchline.protocol.gamecontroller.ReturnPacket;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Turns return-packet messages into referee actions the way the Java HL GameController does:
 * edge-triggered, so only a <em>change</em> of a robot's message counts. A change to
 * MAN_PENALISE asks for penalty MANUAL (15), a change to MAN_UNPENALISE asks to lift it, a
 * change to GOALKEEPER makes the robot goalkeeper. The stored initial message is MAN_PENALISE,
 * so a robot that starts by sending 0 does not penalise itself. The game decides legality.
 */
public final class ManualPenaltyRequests {

    private final Map<Long, Integer> lastMessage = new ConcurrentHashMap<>();

    /** The action this message asks for, or null when it is not an edge (or needs none). */
    public Action onMessage(int team, int player, int message) {
        Integer before = lastMessage.put(((long) team << 16) | player, message);
        int previous = before == null ? ReturnPacket.MAN_PENALISE : before;
        if (previous == message) {
            return null;
        }
        return switch (message) {
            case ReturnPacket.MAN_PENALISE -> new Penalize(team, player, Penalty.MANUAL);
            case ReturnPacket.MAN_UNPENALISE -> new Unpenalize(team, player);
            case ReturnPacket.GOALKEEPER -> new SetGoalkeeper(team, player);
            default -> null;
        };
    }
}
