package touchline.serve;

import java.nio.charset.StandardCharsets;

/** A {@link StateSource} and its channel: sends the state to the subscribers when it changed. */
final class ServedState {

    private final StateSource source;
    private final ServedChannel channel;
    private String last = "";

    ServedState(StateSource source, ChannelTable channels) {
        this.source = source;
        this.channel = channels.addJson(source.topic(), source.schemaName(), source.jsonSchema());
    }

    /** On the server's tick. */
    void poll(long timeNanos) {
        String now = source.now().toString();
        if (channel == null || now.equals(last)) {
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
