package touchline.transport.remote;

/**
 * A robot's Foxglove bridge as {@code listen}, the status bar and the Bridges list say it.
 *
 * @param name        the robot's name
 * @param robotId     the robot number its envelopes carry
 * @param connection  the connection's state, channels and counts (unusable: channels or messages the server
 *                    sent that could not be used; a message that does not decode is counted on the robot)
 * @param serverName  what the server calls itself; "" before it said
 * @param subprotocol {@code foxglove.sdk.v1} or {@code foxglove.websocket.v1}; "" before a connection
 * @param losses      connections lost since the start (each reconnected after the backoff)
 * @param lastCommand the newest command's fate in words; "" when none
 * @param undecodable messages that did not fit their channel's definition, by topic (only topics with any)
 */
public record BridgeStatus(String name, int robotId, RemoteStatus connection, String serverName, String subprotocol,
                           long losses, String lastCommand, java.util.SortedMap<String, Long> undecodable) {

    public boolean online() {
        return connection.state() == RemoteStatus.State.CONNECTED;
    }

    /** One line: "booster-1 ws://10.0.0.5:8765/ connected (foxglove.sdk.v1, 5 channels, 1 200 messages)". */
    public String describe() {
        String counts = connection.channels() + " channels, " + connection.received() + " messages"
                + (connection.unusable() == 0 ? "" : ", " + connection.unusable() + " unusable, the last: "
                + connection.problem())
                + (undecodable.isEmpty() ? "" : ", undecodable: " + undecodable.entrySet().stream()
                        .map(u -> u.getKey() + " " + u.getValue()).collect(java.util.stream.Collectors.joining(", ")))
                + (losses == 0 ? "" : ", " + losses + " reconnection" + (losses == 1 ? "" : "s"));
        return name + " " + connection.url() + " " + switch (connection.state()) {
            case CONNECTING -> "connecting…";
            case CONNECTED -> "connected (" + subprotocol + ", " + counts + ")";
            case LOST -> "lost" + (connection.detail().isEmpty() ? "" : " (" + connection.detail() + ")")
                    + ", reconnecting… (" + counts + ")";
        };
    }
}
