package touchline.serve;

import org.json.JSONObject;

/**
 * A piece of the console's own state served as a JSON channel (schema encoding
 * {@code jsonschema}): polled on the server's tick, sent when it changed and to every new
 * subscriber.
 */
interface StateSource {

    String topic();

    String schemaName();

    /** The JSON Schema of {@link #now()}'s objects. */
    String jsonSchema();

    /** The state now; called on the server's event loop, so it must not block. */
    JSONObject now();
}
