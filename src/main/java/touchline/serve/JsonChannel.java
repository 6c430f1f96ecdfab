package touchline.serve;

import org.json.JSONObject;

import java.util.function.Supplier;

/**
 * A piece of the console's state, given by the face that serves it, as a JSON channel (e.g. the
 * team-message budget meter, {@code /team/budget}): polled on the server's tick; while
 * {@code now} gives null, the channel is not advertised.
 */
public record JsonChannel(String topic, String schemaName, String jsonSchema, Supplier<JSONObject> state)
        implements StateSource {

    @Override
    public JSONObject now() {
        return state.get();
    }
}
