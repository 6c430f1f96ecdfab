package touchline.app.game;

import org.json.JSONObject;

/**
 * Match mode as viewers of the live server see it, the JSON channel {@code /touchline/matchMode}:
 * whether the console may talk to robots, whether play is on (and by which GameController or
 * robot), the override, and the requests held back. The faces hand it to
 * {@code touchline.serve.Serving} as a {@code JsonChannel}; the server knows nothing of match mode.
 */
public final class MatchModeJson {

    public static final String TOPIC = "/touchline/matchMode";
    public static final String SCHEMA_NAME = "touchline.MatchMode";
    public static final String SCHEMA = """
                {"type":"object","properties":{\
                "mayConsoleSend":{"type":"boolean"},"playIsOn":{"type":"boolean"},"overridden":{"type":"boolean"},\
                "notice":{"type":"string"},"heldBack":{"type":"integer"}}}""";

    private final MatchMode matchMode;

    public MatchModeJson(MatchMode matchMode) {
        this.matchMode = matchMode;
    }

    /** Match mode now; never null (the channel is served from the start). */
    public JSONObject now() {
        return new JSONObject().put("mayConsoleSend", matchMode.mayConsoleSend()).put("playIsOn", matchMode.playIsOn())
                .put("overridden", matchMode.isOverridden()).put("notice", matchMode.notice())
                .put("heldBack", matchMode.heldCount());
    }
}
