package touchline.app;

import org.json.JSONObject;

import java.util.function.Supplier;

/**
 * How a face makes one of the console's served state channels (see
 * {@link Console#servedStateChannels}): the live server's {@code touchline.serve.JsonChannel::new}
 * fits, so the core lists its state channels without knowing the server.
 */
@FunctionalInterface
public interface StateChannelMaker<T> {

    /** {@code state} gives the state now as JSON, or null while there is none to serve. */
    T channel(String topic, String schemaName, String jsonSchema, Supplier<JSONObject> state);
}
