package touchline.serve;

import org.json.JSONObject;
import touchline.game.MatchMode;

/**
 * Match mode as viewers see it: whether the console may talk to robots, whether play is on
 * (and by which GameController or robot), the override, and the requests held back.
 */
final class MatchModeState implements StateSource {

    private final MatchMode matchMode;

    MatchModeState(MatchMode matchMode) {
        this.matchMode = matchMode;
    }

    @Override
    public String topic() {
        return "/touchline/matchMode";
    }

    @Override
    public String schemaName() {
        return "touchline.MatchMode";
    }

    @Override
    public String jsonSchema() {
        return """
                {"type":"object","properties":{\
                "mayConsoleSend":{"type":"boolean"},"playIsOn":{"type":"boolean"},"overridden":{"type":"boolean"},\
                "notice":{"type":"string"},"heldBack":{"type":"integer"}}}""";
    }

    @Override
    public JSONObject now() {
        return new JSONObject().put("mayConsoleSend", matchMode.mayConsoleSend()).put("playIsOn", matchMode.playIsOn())
                .put("overridden", matchMode.isOverridden()).put("notice", matchMode.notice())
                .put("heldBack", matchMode.heldCount());
    }
}
