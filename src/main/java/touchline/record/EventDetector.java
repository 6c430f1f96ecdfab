package touchline.record;

import touchline.proto.Fumanoid;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.TeamInfo;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.GameStateReader;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Finds timeline events in an envelope stream: GameController state changes and goals (any
 * game-state format the console recognises on the network, HL v12 to HSL v20; once an HSL
 * GameController's true data for monitors is recorded, it replaces the robots' copy, which
 * shows SET for 10 s after each whistle), players penalised (in any of those formats), game-state changes the robots report in their Status
 * when no GameController packets are recorded, robots silent for five of their periods (the game's:
 * 200 ms, once a second in play; or the robot's own when it sends faster; at least
 * {@link #LOST_AFTER_MICROS}), and link events whose kind says "lost".
 */
final class EventDetector {

    /** Five keep-alive periods without any datagram: the robot counts as lost. */
    static final long LOST_AFTER_MICROS = 1_000_000;
    /** The robots' keep-alive period outside play and in play (READY, SET, PLAYING: the HSL's once a second). */
    static final long PERIOD_MICROS = 200_000;
    static final long PERIOD_IN_PLAY_MICROS = 1_000_000;
    /** Periods of silence after which a robot counts as lost. */
    private static final int LOST_PERIODS = 5;

    private final GameStateReader gameStates = new GameStateReader();
    private final List<TimelineEvent> events = new ArrayList<>();
    private final Map<Integer, Long> lastSeen = new HashMap<>();
    /**
     * Each robot's longest interval between datagrams since the game went into or out of play: a
     * robot that keeps sending faster than the game's rate (five a second in play) is judged by its own.
     */
    private final Map<Integer, Long> period = new HashMap<>();
    /** The newest game state heard, from a GameController or else the robots' status (-1: none yet). */
    private int playState = -1;
    // per direction: a GameController on the network (IN) and the console's own (OUT) are tracked apart
    private final int[] gcState = {-1, -1};
    // scores by team number: the teams swap slots at half time
    @SuppressWarnings("unchecked")
    private final Map<Integer, Integer>[] scores = new Map[]{new HashMap<>(), new HashMap<>()};
    // per direction: each team's players' penalty codes (key team number * 1000 + player number)
    @SuppressWarnings("unchecked")
    private final Map<Integer, Integer>[] penalties = new Map[]{new HashMap<>(), new HashMap<>()};
    private boolean sawGc;
    private boolean sawTrueData;
    private String robotState;
    private long lastTime = Long.MIN_VALUE;

    /** The events of a whole envelope stream, read with {@code next} until it returns null. */
    static List<TimelineEvent> scan(java.util.function.Supplier<Envelope> next) {
        EventDetector detector = new EventDetector();
        for (Envelope e = next.get(); e != null; e = next.get()) {
            detector.accept(e);
        }
        return detector.finish();
    }

    void accept(Envelope e) {
        lastTime = Math.max(lastTime, e.timeMicros());
        if (e.channel() == Channel.GAMECONTROLLER) {
            gameController(e);
        } else if (e.channel() == Channel.LINK_EVENT && e.kind().toLowerCase().contains("lost")) {
            events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.ROBOT_LOST, e.robotId(),
                    "link lost: " + new String(e.raw(), java.nio.charset.StandardCharsets.UTF_8)));
        } else if (e.channel() == Channel.FUMANOID && e.direction() == Direction.IN && e.robotId() >= 0) {
            Long seen = lastSeen.put(e.robotId(), e.timeMicros());
            long lostAfter = lostAfter(e.robotId());
            if (seen != null && e.timeMicros() - seen > lostAfter) {
                events.add(new TimelineEvent(seen + lostAfter, TimelineEvent.Type.ROBOT_LOST, e.robotId(),
                        String.format("robot %d lost (back after %.1f s)", e.robotId(), (e.timeMicros() - seen) / 1e6)));
            } else if (seen != null) {
                period.merge(e.robotId(), e.timeMicros() - seen, Math::max);
            }
            if (!sawGc && e.message() instanceof Fumanoid.Message m && m.hasExtension(Fumanoid.status)) {
                Fumanoid.Status s = m.getExtension(Fumanoid.status);
                if (s.hasGameState() && !s.getGameState().equals(robotState)) {
                    if (robotState != null) {
                        events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.STATE_CHANGE, e.robotId(),
                                "robot " + e.robotId() + ": " + robotState + " → " + s.getGameState()));
                    }
                    robotState = s.getGameState();
                    playState(GameControlData.stateCode(robotState));
                }
            }
        }
    }

    private void gameController(Envelope e) {
        KnownGameStateFormats.Match m = gameStates.read(e);
        if (m == null) {
            return;
        }
        sawTrueData |= m.format().isTrueData();
        if (sawTrueData && !m.format().isTrueData() && e.direction() == Direction.IN) {
            return;
        }
        if (!sawGc) {
            sawGc = true;
            events.removeIf(ev -> ev.type() == TimelineEvent.Type.STATE_CHANGE);
        }
        GameControlData data = m.data();
        int d = e.direction().ordinal();
        String who = e.direction() == Direction.IN ? "GC: " : "our GC: ";
        int state = data.state();
        if (gcState[d] >= 0 && state != gcState[d]) {
            events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.STATE_CHANGE, -1,
                    who + GameControlData.stateName(gcState[d]) + " → " + GameControlData.stateName(state)));
        }
        TeamInfo a = data.teams().get(0);
        TeamInfo b = data.teams().get(1);
        for (TeamInfo team : data.teams()) {
            Integer before = scores[d].put(team.teamNumber(), team.score());
            if (before != null && team.score() > before) {
                events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.GOAL, -1,
                        who + "goal for team " + team.teamNumber() + " (" + a.teamNumber() + " " + a.score() + ":"
                                + b.score() + " " + b.teamNumber() + ")"));
            }
        }
        for (TeamInfo team : data.teams()) {
            for (int n = 1; n <= team.players().size(); n++) {
                int penalty = team.player(n).penalty();
                Integer before = penalties[d].put(team.teamNumber() * 1000 + n, penalty);
                if (before != null && before == 0 && penalty != 0) {
                    events.add(new TimelineEvent(e.timeMicros(), TimelineEvent.Type.PENALTY, -1,
                            who + "team " + team.teamNumber() + " player " + n + " penalised: " + penaltyName(penalty)));
                }
            }
        }
        gcState[d] = state;
        playState(state);
    }

    private void playState(int state) {
        if (GameControlData.isPlay(state) != GameControlData.isPlay(playState)) {
            period.clear(); // the robots change their rate with the game's
        }
        playState = state;
    }

    /**
     * How long a robot may be silent: five of its periods, the game's (once a second in play) or the
     * robot's own when it sends faster, never less than {@link #LOST_AFTER_MICROS}.
     */
    private long lostAfter(int robotId) {
        long game = GameControlData.isPlay(playState) ? PERIOD_IN_PLAY_MICROS : PERIOD_MICROS;
        long own = period.getOrDefault(robotId, game);
        return Math.max(LOST_AFTER_MICROS, LOST_PERIODS * Math.min(game, own));
    }

    private static String penaltyName(int neutralCode) {
        HslPenalty p = HslPenalty.ofNeutral(neutralCode);
        return p == null ? "penalty " + neutralCode : p.name().toLowerCase(java.util.Locale.ROOT).replace('_', ' ');
    }

    List<TimelineEvent> finish() {
        for (Map.Entry<Integer, Long> seen : lastSeen.entrySet()) {
            long lostAfter = lostAfter(seen.getKey());
            if (lastTime - seen.getValue() > lostAfter) {
                events.add(new TimelineEvent(seen.getValue() + lostAfter, TimelineEvent.Type.ROBOT_LOST,
                        seen.getKey(), "robot " + seen.getKey() + " lost"));
            }
        }
        events.sort(Comparator.comparingLong(TimelineEvent::timeMicros));
        return List.copyOf(events);
    }
}
