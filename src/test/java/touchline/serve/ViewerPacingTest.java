package touchline.serve;

import io.netty.buffer.ByteBuf;
import io.netty.channel.embedded.EmbeddedChannel;
import io.netty.handler.codec.http.websocketx.BinaryWebSocketFrame;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * When a viewer's messages leave, on Netty's embedded channel and its fake clock: a message after
 * a quiet spell at once, what arrives within {@link Viewer#SEND_INTERVAL_MILLIS} of a write
 * together at the interval's end, and nothing is held back.
 */
class ViewerPacingTest {

    private final EmbeddedChannel channel = new EmbeddedChannel();
    private final Viewer viewer = new Viewer(channel, new FoxgloveFrames("test", "1"), 100, true);
    private final Subscription subscription = new Subscription(viewer, 7, new ServedChannel(1, "/robot/1/status", "protobuf",
            "touchline.Message", "", "protobuf", null, null));

    @Test
    void aMessageAfterAQuietSpellLeavesAtOnceTheNextOnesTogetherAtTheIntervalsEnd() {
        channel.freezeTime(); // the loop's clock moves only by advanceTimeBy
        viewer.offer(subscription, 1, new byte[] {1});
        channel.runPendingTasks();
        assertEquals(List.of(1), written(), "the first message, after nothing: at once");

        viewer.offer(subscription, 2, new byte[] {2});
        viewer.offer(subscription, 3, new byte[] {3});
        channel.runPendingTasks();
        assertEquals(List.of(), written(), "within the interval after a write: held");
        channel.advanceTimeBy(Viewer.SEND_INTERVAL_MILLIS - 1, TimeUnit.MILLISECONDS);
        channel.runScheduledPendingTasks();
        assertEquals(List.of(), written(), "one millisecond before the interval's end: still held");
        channel.advanceTimeBy(1, TimeUnit.MILLISECONDS);
        channel.runScheduledPendingTasks();
        assertEquals(List.of(2, 3), written(), "at the interval's end, both in one write");

        channel.advanceTimeBy(Viewer.SEND_INTERVAL_MILLIS, TimeUnit.MILLISECONDS);
        channel.runScheduledPendingTasks();
        assertEquals(List.of(), written(), "nothing waited: nothing written");
        viewer.offer(subscription, 4, new byte[] {4});
        channel.runPendingTasks();
        assertEquals(List.of(4), written(), "after a quiet interval: at once again");
    }

    /** The first payload byte of each frame written since the last call. */
    private List<Integer> written() {
        List<Integer> out = new ArrayList<>();
        for (Object o; (o = channel.readOutbound()) != null; ) {
            ByteBuf b = ((BinaryWebSocketFrame) o).content();
            out.add((int) b.getByte(13));
            b.release();
        }
        return out;
    }
}
