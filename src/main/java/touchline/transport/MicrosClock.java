package touchline.transport;

import java.time.Instant;

/** Wall-clock time in microseconds since the epoch; replaced by a fake in tests. */
@FunctionalInterface
public interface MicrosClock {

    long nowMicros();

    static MicrosClock system() {
        return () -> {
            Instant now = Instant.now();
            return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000;
        };
    }
}
