package touchline.model.store;

import org.junit.jupiter.api.Test;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The shelf finds each envelope's data once for the three stores: each still keeps what it kept alone. */
class ViewStoresTest {

    private static final long T0 = 1_700_000_000_000_000L;

    @Test
    void eachStoreKeepsWhatItsKindCarriesAndOnlyWhatRobotsSent() {
        ViewStores stores = new ViewStores(T0);
        stores.live().accept(StoreEnvelopes.text(T0 + 1, 2, "demo.text", "hello"));
        stores.live().accept(StoreEnvelopes.plot(T0 + 2, 2, "demo.plotter", "a", 1.5));
        stores.live().accept(StoreEnvelopes.regions(T0 + 3, 2, "havimo.region", new int[] {0, 0, 10, 10}));
        stores.live().accept(StoreEnvelopes.status(T0 + 4, 2));
        Envelope sent = StoreEnvelopes.text(T0 + 5, 3, "out.text", "sent by the console");
        stores.live().accept(new Envelope(sent.timeMicros(), Direction.OUT, sent.channel(), sent.peer(), 3, sent.kind(),
                sent.message(), sent.raw(), null));
        Envelope noRobot = StoreEnvelopes.text(T0 + 6, 4, "lost.text", "no robot");
        stores.live().accept(new Envelope(noRobot.timeMicros(), Direction.IN, noRobot.channel(), noRobot.peer(), Envelope.NO_ROBOT,
                noRobot.kind(), noRobot.message(), noRobot.raw(), null));

        assertEquals(6, stores.network().size(), "the network log keeps everything, in and out");
        var lines = stores.text().since(0, -1, 10);
        assertEquals(2, lines.size(), "inbound text only, with or without a robot ID");
        assertEquals("hello", lines.get(0).value().text());
        assertEquals("demo.text", lines.get(0).value().option());
        assertEquals("no robot", lines.get(1).value().text());
        assertEquals(1.5, stores.plots().snapshot(2, "demo.plotter").series().get(0).y()[0], 1e-9);
        for (String option : new String[] {"demo.text", "demo.plotter", "havimo.region"}) {
            assertTrue(stores.latest().get(2, option).isPresent(), option);
        }
        assertEquals(3, stores.latest().version(), "latest values: one per data message of a robot, no status");
        assertTrue(stores.latest().get(3, "out.text").isEmpty(), "nothing the console sent");
        assertNull(stores.plots().snapshot(3, "demo.plotter"));
    }
}
