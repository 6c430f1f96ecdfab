package touchline.ui.consoles;

import javafx.collections.FXCollections;
import javafx.collections.ObservableList;
import org.junit.jupiter.api.Test;
import touchline.model.store.SequencedRing;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class RingFollowerTest {

    private final SequencedRing<String> ring = new SequencedRing<>(100);
    private final ObservableList<String> items = FXCollections.observableArrayList();
    private final RingFollower<String, String> follower = new RingFollower<>(items, 5);
    private int reads;

    private SequencedRing.Entry<String> follow() {
        return follower.follow(ring.version(), (after, max) -> {
            reads++;
            return ring.since(after, max);
        }, s -> s.startsWith("skip") ? null : s.toUpperCase());
    }

    @Test
    void appendsOnlyWhatIsNewAndReadsNothingWhenNothingChanged() {
        ring.append("a");
        ring.append("b");
        assertEquals("b", follow().value());
        assertEquals(List.of("A", "B"), items);
        int before = reads;
        assertNull(follow(), "nothing new");
        assertEquals(before, reads, "no read without a new version");
        ring.append("c");
        follow();
        assertEquals(List.of("A", "B", "C"), items);
        assertEquals(1, follower.added());
    }

    @Test
    void keepsTheNewestShownItemsAndSkipsUnmappedOnes() {
        for (int i = 0; i < 8; i++) {
            ring.append("x" + i);
        }
        ring.append("skip me");
        SequencedRing.Entry<String> newest = follow();
        assertEquals("skip me", newest.value(), "the newest read is reported even when not shown");
        assertEquals(List.of("X4", "X5", "X6", "X7"), items);
    }

    @Test
    void reloadStartsAgainFromWhatTheRingHolds() {
        ring.append("a");
        follow();
        items.clear(); // e.g. the user pressed Clear
        ring.append("b");
        follow();
        assertEquals(List.of("B"), items);
        follower.reload();
        follow();
        assertEquals(List.of("A", "B"), items);
    }

    @Test
    void trimsTheOldestInBatchesOfATenth() {
        RingFollower<String, String> twenty = new RingFollower<>(items, 20);
        for (int i = 0; i < 22; i++) {
            ring.append("x" + i);
            twenty.follow(ring.version(), ring::since, s -> s);
        }
        assertEquals(22, items.size(), "up to a tenth over the 20 shown stays");
        assertEquals(0, twenty.trimmed());
        ring.append("x22");
        twenty.follow(ring.version(), ring::since, s -> s);
        assertEquals(3, twenty.trimmed(), "one batch: back to the 20 newest");
        assertEquals(20, items.size());
        assertEquals("x3", items.get(0));
        assertEquals("x22", items.get(19));
    }
}
