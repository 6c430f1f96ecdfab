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

    private static touchline.protocol.ros2.RosMessage joints(double position) {
        return new touchline.protocol.ros2.RosMessage("sensor_msgs/msg/JointState", null,
                new String[] {"name", "position"}, new Object[] {new String[] {"head_yaw"}, new double[] {position}});
    }

    @Test
    void aRosTableIsMadeOnceWhenReadFromTheNewestMessageNotForEveryMessage() {
        java.util.concurrent.atomic.AtomicInteger made = new java.util.concurrent.atomic.AtomicInteger();
        touchline.model.RosTables tables = new touchline.model.RosTables();
        LatestValues latest = new LatestValues((topic, m) -> {
            made.incrementAndGet();
            return tables.table(topic, m);
        });
        for (int i = 1; i <= 100; i++) {
            latest.acceptRos(StoreEnvelopes.ros(i, 1001, "/joint_states", joints(i)));
        }
        assertEquals(0, made.get(), "nothing read yet");
        assertEquals(100, latest.version(), "every message is a change the views notice");
        assertEquals(java.util.List.of(new LatestValues.Key(1001, "/joint_states")),
                latest.translatedSources(java.util.Set.of(Fumanoid.DebugKind.TABLE_VALUE)), "a table view's source at once");

        Latest l = latest.get(1001, "/joint_states").orElseThrow();
        assertEquals(java.util.List.of("head_yaw", "100.000", "", ""), ((Fumanoid.DebugTable) l.data()).getRows(0).getCellsList());
        assertEquals(100, l.timeMicros());
        assertEquals(100, l.version());
        assertEquals("/joint_states", l.kind());
        latest.get(1001, "/joint_states");
        assertEquals(1, latest.ofKind("/joint_states").size());
        assertEquals(1, made.get(), "made once, from the newest");

        latest.acceptRos(StoreEnvelopes.ros(101, 1001, "/joint_states", joints(-2)));
        assertEquals("-2.000", ((Fumanoid.DebugTable) latest.get(1001, "/joint_states").orElseThrow().data()).getRows(0).getCells(1));
        latest.clear();
        assertTrue(latest.get(1001, "/joint_states").isEmpty(), "cleared, the untranslated too");
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
