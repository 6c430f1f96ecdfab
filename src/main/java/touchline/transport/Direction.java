package touchline.transport;

/** Whether an {@link Envelope} came from the field or went out to it. */
public enum Direction {
    IN, OUT
}
