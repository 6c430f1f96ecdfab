package touchline.serve;

import org.json.JSONObject;

import java.nio.charset.StandardCharsets;

/**
 * A {@link StateSource} and its channel: sends the state to the subscribers when it changed. A
 * source whose state is null (nothing to serve yet, e.g. no team's budget guarded) gets its
 * channel advertised when it first has one.
 */
final class ServedState {

    private final StateSource source;
    private final ChannelTable channels;
    private ServedChannel channel;
    private boolean refused;
    private String last = "";

    ServedState(StateSource source, ChannelTable channels) {
        this.source = source;
        this.channels = channels;
        if (source.now() != null) {
            advertise();
        }
    }

    private void advertise() {
        channel = channels.addJson(source.topic(), source.schemaName(), source.jsonSchema());
        refused = channel == null; // the table is full (counted there)
    }

    /** On the server's tick. */
    void poll(long timeNanos) {
        JSONObject state = source.now();
        if (state == null || refused) {
            return;
        }
        if (channel == null) {
            advertise();
            if (refused) {
                return;
            }
        }
        String now = state.toString();
        if (now.equals(last)) {
            return;
        }
        last = now;
        byte[] value = now.getBytes(StandardCharsets.UTF_8);
        channel.setLatest(value);
        for (Subscription s : channel.subscribers()) {
            s.viewer().offer(s, timeNanos, value);
        }
    }
}
