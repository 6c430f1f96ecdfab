package touchline.model.store;

import org.junit.jupiter.api.Test;

import java.util.concurrent.atomic.AtomicBoolean;

import static org.junit.jupiter.api.Assertions.*;

/**
 * Replayed data fills the replay's own stores, never the live robot's of the same number, and a
 * replay's jump empties only those, so a plot after a seek is as if played from there.
 */
class ReplaySandboxStoresTest {

    private final AtomicBoolean showReplay = new AtomicBoolean();
    private final ViewStores stores = new ViewStores(100, 100, 100, 0, showReplay::get);

    @Test
    void replayedDataNeverMixesWithTheLiveRobotsOfTheSameNumber() {
        stores.live().accept(StoreEnvelopes.plot(1_000_000, 3, "speed", "v", 1.0));
        stores.replay().accept(StoreEnvelopes.plot(2_000_000, 3, "speed", "v", 7.0).asReplayed());
        stores.replay().accept(StoreEnvelopes.text(2_000_000, 3, "log", "from the recording").asReplayed());

        assertEquals(1, stores.live().plots().snapshot(3, "speed").series().get(0).count());
        assertEquals(1.0, stores.live().plots().snapshot(3, "speed").series().get(0).y()[0]);
        assertEquals(7.0, stores.replay().plots().snapshot(3, "speed").series().get(0).y()[0]);
        assertEquals(0, stores.live().text().size());
        assertEquals(1, stores.replay().text().size());

        assertSame(stores.live().plots(), stores.plots(), "the views show the live stores ...");
        showReplay.set(true);
        assertSame(stores.replay().plots(), stores.plots(), "... or the replay's, when it plays alone");
    }

    @Test
    void aJumpEmptiesTheReplaysStoresOnlyAndTheViewsNoticeTheNextValue() {
        stores.live().accept(StoreEnvelopes.plot(1_000_000, 3, "speed", "v", 1.0));
        for (int i = 0; i < 5; i++) {
            stores.replay().accept(StoreEnvelopes.plot(10_000_000 + i * 100_000L, 3, "speed", "v", i).asReplayed());
        }
        stores.replay().accept(StoreEnvelopes.text(10_000_000, 3, "log", "before the seek").asReplayed());
        long plotVersion = stores.replay().plots().version(3, "speed");
        long textSeq = stores.replay().text().version();
        long latestVersion = stores.replay().latest().version();

        stores.restartReplay(9_000_000);
        assertNull(stores.replay().plots().snapshot(3, "speed"));
        assertTrue(stores.replay().latest().get(3, "speed").isEmpty());
        assertEquals(0, stores.replay().text().size());
        assertEquals(1, stores.live().plots().snapshot(3, "speed").series().get(0).count(), "live data stays");

        stores.replay().accept(StoreEnvelopes.plot(10_000_000, 3, "speed", "v", 42).asReplayed());
        stores.replay().accept(StoreEnvelopes.text(10_000_000, 3, "log", "after the seek").asReplayed());
        PlotStore.SeriesData after = stores.replay().plots().snapshot(3, "speed").series().get(0);
        assertEquals(1, after.count(), "as if played from the seek");
        assertEquals(1.0, after.x()[0], 1e-9, "seconds from the replay's origin");
        assertTrue(stores.replay().plots().version(3, "speed") > plotVersion, "a view sees the plot changed");
        assertTrue(stores.replay().latest().version() > latestVersion);
        var lines = stores.replay().text().since(textSeq, -1, 10);
        assertEquals(1, lines.size(), "a view following the log gets what came after the seek");
        assertEquals("after the seek", lines.get(0).value().text());
    }
}
