package touchline.transport.gamecontroller;

import java.time.Instant;

/** Envelope time stamps: microseconds since the epoch. */
final class Clock {
    private Clock() {
    }

    static long micros() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }
}
