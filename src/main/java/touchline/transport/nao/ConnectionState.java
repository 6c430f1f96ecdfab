package touchline.transport.nao;

/** What the console knows about its link to a NAO, as the UI shows it. */
public enum ConnectionState {
    /** Connecting for the first time; calls wait (within their timeout) for the link to come up. */
    CONNECTING,
    /** The ZMTP handshake completed: a live peer answered (a bare TCP connect does not count). */
    ONLINE,
    /** Disconnected or heartbeat timeout; calls fail at once as {@link CallOutcome.Lost} until ONLINE again. */
    LOST,
    /**
     * The CURVE handshake failed (the NAO refused our key, or we have the wrong key for it):
     * calls fail at once with {@link NaoLink#securityProblem()}; the link keeps retrying and goes
     * ONLINE as soon as a handshake succeeds (e.g. the NAO was given console.public and restarted).
     */
    REFUSED,
    /** The link was closed by the console. */
    CLOSED
}
