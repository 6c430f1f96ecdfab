package touchline.transport.remote;

/** A message or service request made ready for a server, or why it cannot go. */
sealed interface Outgoing {

    /**
     * @param encoding {@code cdr} or {@code json}
     * @param schema   the ROS 2 definition a CDR payload was written by (for the client's advertise); null for JSON
     * @param payload  the message's bytes
     */
    record Ready(String encoding, BridgedSchema schema, byte[] payload) implements Outgoing { }

    /** A sentence for the user: the values do not fit the definition, no definition is known, the server takes neither. */
    record Refused(String reason) implements Outgoing { }
}
