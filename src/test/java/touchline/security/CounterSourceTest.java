package touchline.security;

import org.junit.jupiter.api.Test;

import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.*;

class CounterSourceTest {

    @Test
    void followsTheClockAndStillIncreasesWhenItJumpsBack() {
        AtomicLong clock = new AtomicLong(1_000_000_000L);
        CounterSource c = new CounterSource(clock::get, CounterSource.inMemory());
        long a = c.next();
        assertEquals(1_000_000_000L, a);
        assertEquals(a + 1, c.next(), "the same microsecond: last + 1");
        clock.set(2_000_000_000L);
        long b = c.next();
        assertEquals(2_000_000_000L, b);
        clock.set(1_000L); // the clock jumps back an age
        assertEquals(b + 1, c.next());
    }

    @Test
    void aNewRunStartsAboveEverythingTheLastRunCouldHaveSent() {
        AtomicLong clock = new AtomicLong(5_000_000L);
        CounterSource.Store store = CounterSource.inMemory();
        CounterSource first = new CounterSource(clock::get, store);
        long last = 0;
        for (int i = 0; i < 1000; i++) {
            last = first.next();
        }
        assertTrue(store.load() > last, "the reservation covers every counter handed out");
        clock.set(1_000L); // the next run's clock is behind
        CounterSource second = new CounterSource(clock::get, store);
        assertTrue(second.next() > last);
    }

    @Test
    void theStoreIsWrittenOncePerReservationNotPerCounter() {
        AtomicLong clock = new AtomicLong(1_000_000L);
        int[] saves = {0};
        CounterSource.Store memory = CounterSource.inMemory();
        CounterSource.Store counting = new CounterSource.Store() {
            @Override
            public long load() {
                return memory.load();
            }

            @Override
            public void save(long reservedUpTo) {
                memory.save(reservedUpTo);
                saves[0]++;
            }
        };
        CounterSource c = new CounterSource(clock::get, counting);
        for (int i = 0; i < 10_000; i++) {
            c.next();
            clock.addAndGet(100); // 10 000 datagrams over one second
        }
        assertEquals(1, saves[0]);
    }
}
