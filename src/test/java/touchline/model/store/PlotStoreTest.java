package touchline.model.store;

import com.google.protobuf.ByteString;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

class PlotStoreTest {

    private static final long T0 = 1_700_000_000_000_000L;

    @Test
    void xIsSecondsSinceTheOriginAndSeriesAreKeptApart() {
        PlotStore store = new PlotStore(100, T0);
        store.accept(StoreEnvelopes.plot(T0 + 1_000_000, 1, "p", "a", 1.0));
        store.accept(StoreEnvelopes.plot(T0 + 2_500_000, 1, "p", "a", 2.0));
        store.accept(StoreEnvelopes.plot(T0 + 2_500_000, 1, "p", "b", 7.0));
        PlotStore.Snapshot s = store.snapshot(1, "p");
        assertEquals(2, s.series().size());
        PlotStore.SeriesData a = s.series().get(0);
        assertEquals(2, a.count());
        assertEquals(1.0, a.x()[0], 1e-9);
        assertEquals(2.5, a.x()[1], 1e-9);
        assertEquals(2.0, a.y()[1], 1e-9);
        assertNull(store.snapshot(2, "p"));
    }

    @Test
    void skipsAndCountsNonFiniteValues() {
        PlotStore store = new PlotStore(100, T0);
        store.accept(StoreEnvelopes.plot(T0 + 1, 1, "p", "a", Double.NaN));
        store.accept(StoreEnvelopes.plot(T0 + 2, 1, "p", "a", 3.0));
        store.accept(StoreEnvelopes.plot(T0 + 3, 1, "p", "a", Double.POSITIVE_INFINITY));
        PlotStore.Snapshot s = store.snapshot(1, "p");
        assertEquals(2, s.skippedNonFinite());
        assertEquals(1, s.series().get(0).count());
        assertEquals(3.0, s.series().get(0).y()[0]);
    }

    @Test
    void decimatesABurstOfTenThousandPointsKeepingItsExtremes() {
        PlotStore store = new PlotStore(4000, T0);
        double[] burst = new double[10_000];
        for (int i = 0; i < burst.length; i++) {
            burst[i] = Math.sin(i / 100.0);
        }
        burst[4321] = 99.0; // a spike must survive decimation
        store.accept(StoreEnvelopes.plot(T0 + 1_000_000, 1, "p", "a", burst));
        PlotStore.Snapshot s = store.snapshot(1, "p");
        PlotStore.SeriesData a = s.series().get(0);
        assertEquals(PlotStore.BURST_LIMIT, a.count());
        assertEquals(1, s.decimatedBursts());
        double max = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < a.count(); i++) {
            max = Math.max(max, a.y()[i]);
            if (i > 0) {
                assertTrue(a.x()[i] >= a.x()[i - 1], "x must not run backwards");
            }
        }
        assertEquals(99.0, max);
    }

    @Test
    void aSnapshotCopiesIntoTheArraysOfTheOneBeforeAndShowsOnlyTheNewPoints() {
        PlotStore store = new PlotStore(10, T0);
        store.accept(StoreEnvelopes.plot(T0 + 1_000_000, 1, "p", "a", 1.0));
        store.accept(StoreEnvelopes.plot(T0 + 1_000_000, 1, "p", "b", 5.0));
        PlotStore.Snapshot first = store.snapshot(1, "p", null);
        store.accept(StoreEnvelopes.plot(T0 + 2_000_000, 1, "p", "a", 2.0));
        PlotStore.Snapshot second = store.snapshot(1, "p", first);
        for (int k = 0; k < 2; k++) {
            assertSame(first.series().get(k).x(), second.series().get(k).x(), "no new arrays for series " + k);
            assertSame(first.series().get(k).y(), second.series().get(k).y());
        }
        assertEquals(2, second.series().get(0).count());
        assertEquals(2.0, second.series().get(0).y()[1], 1e-9);
        assertEquals(1, second.series().get(1).count());
        assertEquals(5.0, second.series().get(1).y()[0], 1e-9);
    }

    @Test
    void ringDropsTheOldestPoints() {
        PlotStore store = new PlotStore(10, T0);
        for (int i = 0; i < 25; i++) {
            store.accept(StoreEnvelopes.plot(T0 + i * 1000L, 1, "p", "a", i));
        }
        PlotStore.SeriesData a = store.snapshot(1, "p").series().get(0);
        assertEquals(10, a.count());
        assertEquals(15.0, a.y()[0]);
        assertEquals(24.0, a.y()[9]);
        assertEquals(25, store.version(1, "p"));
    }

    /**
     * Series names are looked up by their bytes (decoded once); two byte sequences that decode
     * to the same name (invalid UTF-8 becomes U+FFFD) are still one series, as their names are.
     */
    @Test
    void seriesAreTheirDecodedNamesWhateverBytesSpelledThem() throws Exception {
        PlotStore store = new PlotStore(1_000, T0);
        Fumanoid.DebugPlot.Builder plot = Fumanoid.DebugPlot.newBuilder().setOption("p");
        plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeriesBytes(ByteString.copyFrom(new byte[] {(byte) 0xff})).setValue(1));
        plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeriesBytes(ByteString.copyFrom(new byte[] {(byte) 0xfe})).setValue(2));
        plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeries("ok").setValue(3));
        byte[] wire = Fumanoid.Message.newBuilder().setRobotID(1).setExtension(Fumanoid.debugPlot, plot.build()).build().toByteArray();
        Fumanoid.Message parsed = Fumanoid.Message.parseFrom(wire, new touchline.protocol.MessageKinds().registry());
        for (int i = 1; i <= 300; i++) {
            store.accept(StoreEnvelopes.in(T0 + i * 1_000_000L, 1, "debugPlot",
                    Fumanoid.Message.parseFrom(wire, new touchline.protocol.MessageKinds().registry())));
        }
        PlotStore.Snapshot s = store.snapshot(1, parsed.getExtension(Fumanoid.debugPlot).getOption());
        assertEquals(2, s.series().size(), "\ufffd and ok");
        assertEquals("\ufffd", s.series().get(0).name());
        assertEquals(600, s.series().get(0).count(), "both values of each message, spread over its interval");
        assertEquals(300, s.series().get(1).count());
        assertEquals(3.0, s.series().get(1).y()[299], 1e-9);
    }
}
