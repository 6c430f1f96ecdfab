package touchline.serve;

import org.json.JSONArray;
import org.json.JSONObject;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.RobotInfo;
import touchline.protocol.gamecontroller.TeamInfo;
import touchline.transport.Envelope;
import touchline.transport.GameStateReader;

import java.nio.charset.StandardCharsets;

/**
 * The GameController's game state as the JSON channel {@code /gc/state}: every game-state
 * packet the console hears (or its embedded GameController sends), decoded by the known
 * formats: state, half, clock, set play, and per team the score, message budget and each
 * player's penalty. A new subscriber gets the last one at once.
 */
final class GameControllerState {

    static final String SCHEMA = """
            {"type":"object","properties":{\
            "format":{"type":"string"},"source":{"type":"string"},"state":{"type":"string"},\
            "firstHalf":{"type":"boolean"},"secsRemaining":{"type":"integer"},"secondaryTime":{"type":"integer"},\
            "secondaryState":{"type":"integer"},"gamePhase":{"type":"integer"},"kickOffTeam":{"type":"integer"},\
            "stopped":{"type":"boolean"},"teams":{"type":"array","items":{"type":"object","properties":{\
            "teamNumber":{"type":"integer"},"score":{"type":"integer"},"messageBudget":{"type":"integer"},\
            "players":{"type":"array","items":{"type":"object","properties":{\
            "penalty":{"type":"integer"},"secsTillUnpenalised":{"type":"integer"}}}}}}}}}""";

    private final GameStateReader gameStates = new GameStateReader();
    private final ServedChannel channel;

    GameControllerState(ChannelTable channels) {
        this.channel = channels.addJson("/gc/state", "touchline.GameControllerState", SCHEMA);
    }

    /** Serves {@code e} when it is a well-formed game-state packet. */
    void accept(Envelope e) {
        KnownGameStateFormats.Match m = channel == null ? null : gameStates.read(e);
        if (m == null) {
            return;
        }
        byte[] json = json(m, e).toString().getBytes(StandardCharsets.UTF_8);
        channel.setLatest(json);
        long nanos = e.timeMicros() * 1000;
        for (Subscription s : channel.subscribers()) {
            s.viewer().offer(s, nanos, json);
        }
    }

    private static JSONObject json(KnownGameStateFormats.Match m, Envelope e) {
        GameControlData d = m.data();
        JSONArray teams = new JSONArray();
        for (TeamInfo t : d.teams()) {
            JSONArray players = new JSONArray();
            for (RobotInfo r : t.players()) {
                players.put(new JSONObject().put("penalty", r.penalty()).put("secsTillUnpenalised", r.secsTillUnpenalised()));
            }
            teams.put(new JSONObject().put("teamNumber", t.teamNumber()).put("score", t.score())
                    .put("messageBudget", t.messageBudget()).put("players", players));
        }
        return new JSONObject().put("format", m.format().kind())
                .put("source", e.direction().name() + (e.peer() == null ? "" : " " + e.peer().getHostString()))
                .put("state", GameControlData.stateName(d.state())).put("firstHalf", d.firstHalf())
                .put("secsRemaining", d.secsRemaining()).put("secondaryTime", d.secondaryTime())
                .put("secondaryState", d.secondaryState()).put("gamePhase", d.gamePhase())
                .put("kickOffTeam", d.kickOffTeam()).put("stopped", d.stopped()).put("teams", teams);
    }
}
