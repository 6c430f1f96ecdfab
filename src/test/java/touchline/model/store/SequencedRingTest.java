package touchline.model.store;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class SequencedRingTest {

    @Test
    void keepsOnlyTheNewestCapacityEntriesAndNumbersThem() {
        SequencedRing<String> ring = new SequencedRing<>(3);
        for (int i = 1; i <= 5; i++) {
            ring.append("e" + i);
        }
        assertEquals(5, ring.version());
        assertEquals(3, ring.size());
        List<SequencedRing.Entry<String>> all = ring.since(0, 100);
        assertEquals(List.of("e3", "e4", "e5"), all.stream().map(SequencedRing.Entry::value).toList());
        assertEquals(3, all.get(0).seq());
    }

    @Test
    void sinceReturnsOnlyNewerMatchingEntriesCappedToTheNewest() {
        SequencedRing<Integer> ring = new SequencedRing<>(100);
        for (int i = 1; i <= 10; i++) {
            ring.append(i);
        }
        assertEquals(List.of(9, 10), ring.since(8, 100).stream().map(SequencedRing.Entry::value).toList());
        assertEquals(List.of(8, 10), ring.since(0, 2, v -> v % 2 == 0).stream().map(SequencedRing.Entry::value).toList());
        assertTrue(ring.since(10, 100).isEmpty());
    }

    @Test
    void refusesANonPositiveCapacity() {
        assertThrows(IllegalArgumentException.class, () -> new SequencedRing<>(0));
    }

    @Test
    void concurrentWritersLoseNothingButTheOverflow() throws InterruptedException {
        SequencedRing<Integer> ring = new SequencedRing<>(1000);
        Thread[] writers = new Thread[4];
        for (int w = 0; w < writers.length; w++) {
            writers[w] = new Thread(() -> {
                for (int i = 0; i < 10_000; i++) {
                    ring.append(i);
                }
            });
            writers[w].start();
        }
        for (Thread t : writers) {
            t.join();
        }
        assertEquals(40_000, ring.version());
        assertEquals(1000, ring.since(0, 5000).size());
    }
}
