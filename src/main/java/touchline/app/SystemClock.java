package touchline.app;

import touchline.game.GameClock;
import touchline.record.PlaybackClock;
import touchline.transport.MicrosClock;
import touchline.transport.MonotonicClock;

import java.time.Instant;

/**
 * The real clock, the one place in the product that reads the system's time ({@code
 * ArchitectureTest} forbids it everywhere else). Made once at the top (the {@link Console}, a
 * command that has no console) and handed down through constructors in the shape each part
 * asks for: wall time in microseconds for envelopes and models ({@link MicrosClock}),
 * monotonic milliseconds for the game ({@link GameClock}), monotonic nanoseconds for the NAO
 * link's deadlines ({@link MonotonicClock}) and replay pacing ({@link PlaybackClock}, one of
 * those). Tests hand down fakes instead.
 */
public final class SystemClock implements MicrosClock, MonotonicClock, GameClock, PlaybackClock {

    /** Wall time, microseconds since the epoch. */
    @Override
    public long nowMicros() {
        Instant now = Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }

    /** Monotonic, milliseconds (unaffected by changes of the wall clock). */
    @Override
    public long millis() {
        return System.nanoTime() / 1_000_000L;
    }

    /** Monotonic, nanoseconds. */
    @Override
    public long nanoTime() {
        return System.nanoTime();
    }

    /** Wall time as an instant (file names, key dates). */
    public Instant instant() {
        return Instant.now();
    }
}
