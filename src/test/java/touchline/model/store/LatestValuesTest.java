package touchline.model.store;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class LatestValuesTest {

    @Test
    void keepsOnlyTheNewestValuePerRobotAndOption() {
        LatestValues latest = new LatestValues();
        latest.accept(StoreEnvelopes.image(10, 1, "demo.image", 2, 2, 0, new byte[4]));
        latest.accept(StoreEnvelopes.image(20, 1, "demo.image", 4, 4, 0, new byte[16]));
        latest.accept(StoreEnvelopes.image(30, 2, "demo.image", 1, 1, 0, new byte[1]));
        Latest l = latest.get(1, "demo.image").orElseThrow();
        assertEquals(20, l.timeMicros());
        assertEquals(4, ((Fumanoid.DebugImage) l.data()).getWidth());
        assertEquals("debugImage", l.kind());
        assertEquals(2, latest.ofKind("debugImage").size());
        assertEquals(3, latest.version());
        assertTrue(latest.get(3, "demo.image").isEmpty());
    }

    @Test
    void viewStoresFeedEveryStoreFromOneEnvelope() {
        ViewStores stores = new ViewStores(100, 100, 100, 0);
        stores.live().accept(StoreEnvelopes.text(5, 1, "demo.text", "hello"));
        assertEquals(1, stores.text().version());
        assertEquals(1, stores.network().version());
        assertEquals("hello", ((Fumanoid.DebugText) stores.latest().get(1, "demo.text").orElseThrow().data()).getText());
    }

    @Test
    void networkLogIsBounded() {
        NetworkLog log = new NetworkLog(5);
        for (int i = 0; i < 12; i++) {
            log.accept(StoreEnvelopes.text(i, 1, "t", "x"));
        }
        assertEquals(5, log.size());
        assertEquals(12, log.version());
        assertEquals(7, log.since(0, 100, e -> true).get(0).value().timeMicros());
    }
}
