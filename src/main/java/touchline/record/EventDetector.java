package touchline.record;

import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Finds timeline events in an envelope stream: GameController state changes and goals (HL
 * v12 "RGme": state byte 9, scores at 24+2 and 356+2), game-state changes the robots report
 * in their Status when no GameController packets are recorded, robots silent for longer
 * than {@link #LOST_AFTER_MICROS}, and link events whose kind says "lost".
 */
final class EventDetector {

    /** Five keep-alive periods without any datagram: the robot counts as lost. */
    static final long LOST_AFTER_MICROS = 1_000_000;
    private static final String[] GC_STATES = {"INITIAL", "READY", "SET", "PLAYING", "FINISHED"};

    private final List<TimelineEvent> events = new ArrayList<>();
    private final Map<Integer, Long> lastSeen = new HashMap<>();
    private int gcState = -1;
    private int score0 = -1;
    private int score1 = -1;
    private boolean sawGc;
    private String robotState;
    private long lastTime = Long.MIN_VALUE;

    void accept(Envelope e) {
        lastTime = Math.max(lastTime, e.timeMicros());
        if (e.channel() == Channel.GAMECONTROLLER) {
            gameController(e);
        } else if (e.channel() == Channel.LINK_EVENT && e.kind().toLowerCase().contains("lost")) {
            events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.ROBOT_LOST, e.robotId(),
                    "link lost: " + new String(e.raw(), java.nio.charset.StandardCharsets.UTF_8)));
        } else if (e.channel() == Channel.FUMANOID && e.direction() == Direction.IN && e.robotId() >= 0) {
            Long seen = lastSeen.put(e.robotId(), e.timeMicros());
            if (seen != null && e.timeMicros() - seen > LOST_AFTER_MICROS) {
                events.add(new TimelineEvent(seen + LOST_AFTER_MICROS, TimelineEvent.Type.ROBOT_LOST, e.robotId(),
                        String.format("robot %d lost (back after %.1f s)", e.robotId(), (e.timeMicros() - seen) / 1e6)));
            }
            if (!sawGc && e.message() instanceof Fumanoid.Message m && m.hasExtension(Fumanoid.status)) {
                Fumanoid.Status s = m.getExtension(Fumanoid.status);
                if (s.hasGameState() && !s.getGameState().equals(robotState)) {
                    if (robotState != null) {
                        events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.STATE_CHANGE, e.robotId(),
                                "robot " + e.robotId() + ": " + robotState + " → " + s.getGameState()));
                    }
                    robotState = s.getGameState();
                }
            }
        }
    }

    private void gameController(Envelope e) {
        byte[] r = e.raw();
        if (r.length != 688 || r[0] != 'R' || r[1] != 'G' || r[2] != 'm' || r[3] != 'e' || r[4] != 12) {
            return;
        }
        if (!sawGc) {
            sawGc = true;
            events.removeIf(ev -> ev.type() == TimelineEvent.Type.STATE_CHANGE);
        }
        int state = r[9] & 0xFF;
        int s0 = r[24 + 2] & 0xFF;
        int s1 = r[356 + 2] & 0xFF;
        if (gcState >= 0 && state != gcState) {
            events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.STATE_CHANGE, -1,
                    "GC: " + stateName(gcState) + " → " + stateName(state)));
        }
        if (score0 >= 0 && (s0 > score0 || s1 > score1)) {
            int team = s0 > score0 ? r[24] & 0xFF : r[356] & 0xFF;
            events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.GOAL, -1,
                    "goal for team " + team + " (" + s0 + ":" + s1 + ")"));
        }
        gcState = state;
        score0 = s0;
        score1 = s1;
    }

    private static String stateName(int s) {
        return s < GC_STATES.length ? GC_STATES[s] : "state " + s;
    }

    List<TimelineEvent> finish() {
        for (Map.Entry<Integer, Long> seen : lastSeen.entrySet()) {
            if (lastTime - seen.getValue() > LOST_AFTER_MICROS) {
                events.add(new TimelineEvent(seen.getValue() + LOST_AFTER_MICROS, TimelineEvent.Type.ROBOT_LOST,
                        seen.getKey(), "robot " + seen.getKey() + " lost"));
            }
        }
        events.sort(Comparator.comparingLong(TimelineEvent::timeMicros));
        return List.copyOf(events);
    }
}
