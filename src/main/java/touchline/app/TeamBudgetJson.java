package touchline.app;

import org.json.JSONObject;
import touchline.model.TeamMessageBudget;

import java.util.Optional;
import java.util.function.Supplier;

/**
 * The team-message budget meter as the JSON channel {@code /team/budget}: messages used and left,
 * those heard but not counted (outside READY, SET and PLAYING, or before a GameController was heard;
 * and whether the figure is the GameController's own), the rate over the last minute, the rule
 * profile's limit, the forecast and oversize messages. Served only while the console guards a
 * team's budget ({@code --team}); the channel is advertised once the guard runs
 * ({@code touchline.serve.JsonChannel} serves it).
 */
public final class TeamBudgetJson {

    public static final String TOPIC = "/team/budget";
    public static final String SCHEMA_NAME = "touchline.TeamBudget";
    public static final String SCHEMA = """
                {"type":"object","properties":{\
                "team":{"type":"integer"},"profile":{"type":"string"},"limit":{"type":"string"},\
                "used":{"type":"integer"},"notCounted":{"type":"integer"},"gameControllerHeard":{"type":"boolean"},"left":{"type":"integer"},"leftFromGc":{"type":"boolean"},\
                "perMinute":{"type":"number"},"secondsLeftInGame":{"type":"integer"},"secondsToEmpty":{"type":"integer"},\
                "verdict":{"type":"string"},"oversize":{"type":"integer"},"summary":{"type":"string"}}}""";

    private final Supplier<Optional<TeamMessageBudget>> budget;

    TeamBudgetJson(Supplier<Optional<TeamMessageBudget>> budget) {
        this.budget = budget;
    }

    /** The meter now; null while no budget is guarded (the channel is not served then). */
    public JSONObject now() {
        return budget.get().map(b -> json(b.snapshot())).orElse(null);
    }

    private static JSONObject json(TeamMessageBudget.Snapshot s) {
        // the rate is rounded to a tenth, so the channel does not send a new value every tick for noise
        return new JSONObject().put("team", s.team()).put("profile", s.profile().name())
                .put("limit", s.profile().teamMessageBudget().describe()).put("used", s.used()).put("left", s.left())
                .put("notCounted", s.notCounted()).put("gameControllerHeard", s.gameControllerHeard())
                .put("leftFromGc", s.leftFromGc()).put("perMinute", Math.round(s.perMinute() * 10) / 10.0)
                .put("secondsLeftInGame", s.secondsLeftInGame()).put("secondsToEmpty", s.secondsToEmpty())
                .put("verdict", s.verdict().name()).put("oversize", s.oversize()).put("summary", s.describe());
    }
}
