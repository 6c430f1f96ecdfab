package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Pausing live listening while a replay runs: paused envelopes are counted, not passed on and not queued. */
class LiveSwitchTest {

    private final List<Envelope> passed = new ArrayList<>();
    private final LiveSwitch live = new LiveSwitch(passed::add);

    private static Envelope status(long time) {
        return new Envelope(time, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 40001), 1,
                "status", null, new byte[8], null);
    }

    @Test
    void liveEnvelopesPassThrough() {
        Envelope e = status(1);
        live.accept(e);

        assertTrue(live.isLive());
        assertEquals(List.of(e), passed);
        assertEquals(0, live.skipped());
    }

    @Test
    void pausedEnvelopesAreCountedAndDroppedAndResumingDoesNotReplayThem() {
        live.setLive(false);
        live.accept(status(1));
        live.accept(status(2));
        assertFalse(live.isLive());
        assertEquals(List.of(), passed);
        assertEquals(2, live.skipped());

        live.setLive(true);
        Envelope after = status(3);
        live.accept(after);
        assertEquals(List.of(after), passed, "nothing queued while paused comes out on resume");
        assertEquals(2, live.skipped());
    }
}
