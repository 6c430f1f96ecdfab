package touchline.transport;

/**
 * Where an {@link Envelope} comes from: the live field (a socket, a call, the console's own
 * sending) or a recording played back. A replay never acts on the live field, so everything
 * that sends to robots or decides match mode listens to {@link #LIVE} envelopes only.
 * {@link #REMOTE} envelopes come from another Touchline's stream (this console as its viewer):
 * the model shows them like live robots, but a console viewing a remote stream sends nothing.
 */
public enum Origin {
    LIVE,
    REPLAY,
    REMOTE
}
