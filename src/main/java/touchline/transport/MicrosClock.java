package touchline.transport;

/** Wall-clock time in microseconds since the epoch: the real one is {@code app.SystemClock}; tests pass a fake. */
@FunctionalInterface
public interface MicrosClock {

    long nowMicros();
}
