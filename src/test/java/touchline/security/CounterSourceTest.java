package touchline.security;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
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
    void aNewRunStartsAboveEverythingTheLastRunSent(@TempDir Path dir) {
        AtomicLong clock = new AtomicLong(5_000_000L);
        KeyDir keys = new KeyDir(dir);
        CounterSource first = new CounterSource(clock::get, keys.counterStore());
        long last = 0;
        for (int i = 0; i < 100; i++) {
            last = first.next();
        }
        clock.set(1_000L); // the next run's clock is behind
        CounterSource second = new CounterSource(clock::get, new KeyDir(dir).counterStore());
        assertTrue(second.next() > last);
    }

    /**
     * The window and {@code touchline options} on one laptop, each with its own store of the one
     * key directory, sending in turn: every counter is above every counter sent before it, by
     * either (a robot keeps only the highest and refuses the rest as replayed).
     */
    @Test
    void twoConsolesOfOneLaptopNeverGoBackAgainstEachOther(@TempDir Path dir) {
        AtomicLong clock = new AtomicLong(1_000_000L);
        CounterSource window = new CounterSource(clock::get, new KeyDir(dir).counterStore());
        long highest = window.next();
        CounterSource options = new CounterSource(clock::get, new KeyDir(dir).counterStore());
        for (int i = 0; i < 50; i++) {
            clock.addAndGet(1_000);
            CounterSource who = i % 3 == 0 ? options : window;
            long c = who.next();
            assertTrue(c > highest, "datagram " + i + ": " + c + " after " + highest);
            highest = c;
        }
    }
}
