package touchline.transport.nao;

import touchline.transport.MicrosClock;
import touchline.transport.MonotonicClock;

/**
 * Known debt: the time of the {@link NaoLink} and {@link NaoCameraStream} constructors that are
 * not handed a clock (kept so their callers compile; {@code app.NaoSession} and the tests move
 * to the constructors taking the console's clock). The one class of this package that reads
 * the system's time; {@code ArchitectureTest} names it. Stateless.
 */
final class UninjectedClock implements MicrosClock, MonotonicClock {

    @Override
    public long nowMicros() {
        java.time.Instant now = java.time.Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1000;
    }

    @Override
    public long nanoTime() {
        return System.nanoTime();
    }
}
