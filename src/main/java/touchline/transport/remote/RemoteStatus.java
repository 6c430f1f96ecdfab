package touchline.transport.remote;

/**
 * Where the connection to the remote Touchline stands, as the status bar and {@code listen
 * --connect} say it.
 *
 * @param state    connecting, connected, or lost (and reconnecting by itself)
 * @param url      the server's address without its token
 * @param detail   why the connection was lost or refused, or the server's last status message; "" when none
 * @param channels robot channels subscribed to
 * @param received envelopes rebuilt from the stream since the start
 * @param unusable messages or channels from the server that could not be used (counted)
 * @param problem  the newest of those, in a sentence; "" when none
 */
public record RemoteStatus(State state, String url, String detail, int channels, long received, long unusable,
                           String problem) {

    public enum State { CONNECTING, CONNECTED, LOST }

    /** One line for a person: "viewing ws://… (connected, 12 channels)" or "connection lost (…), reconnecting…". */
    public String describe() {
        return switch (state) {
            case CONNECTING -> "connecting to " + url + "…";
            case CONNECTED -> "viewing " + url + " (connected, " + channels + " channels"
                    + (unusable == 0 ? "" : ", " + unusable + " unusable, the last: " + problem) + ")";
            case LOST -> "connection to " + url + " lost" + (detail.isEmpty() ? "" : " (" + detail + ")")
                    + ", reconnecting…";
        };
    }
}
