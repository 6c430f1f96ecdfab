package touchline.app;

import org.junit.jupiter.api.Test;
import touchline.proto.Nao.CamResponse;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.Origin;

import java.io.IOException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.testing.NaoCameraEnvelopes.CAMERA;
import static touchline.testing.NaoCameraEnvelopes.frame;
import static touchline.testing.NaoCameraEnvelopes.jpeg;

/** The NAO cameras' newest frame read from the Envelope stream, on fake clocks. */
class NaoCameraFeedTest {

    private final AtomicLong now = new AtomicLong(1_000_000);
    private final AtomicLong replayPosition = new AtomicLong(500);
    private final AtomicBoolean replaying = new AtomicBoolean();
    private final NaoCameraFeed feed = new NaoCameraFeed(now::get, replayPosition::get, replaying::get);

    /** As the console's two streams hand it on: a replayed envelope to the replay's slot, any other to the live one. */
    private void publish(Envelope e) {
        (e.replayed() ? feed.replay() : feed.live()).accept(e);
    }

    @Test
    void keepsTheNewestFrameWithItsSizeTimeAndSource() throws IOException {
        assertTrue(feed.latest().isEmpty());
        byte[] first = jpeg(160, 120);
        byte[] second = jpeg(320, 240);
        publish(frame(first, 10, Origin.LIVE));
        publish(frame(second, 20, Origin.REMOTE)); // a remote Touchline's frame counts as the field's
        NaoFrame f = feed.latest().orElseThrow();
        assertArrayEquals(second, f.jpeg());
        assertEquals(320, f.width());
        assertEquals(240, f.height());
        assertEquals(2, f.sequence());
        assertEquals(20, f.timeMicros());
        assertEquals("10.0.0.7:5556", f.source());
    }

    @Test
    void ignoresWhatIsNoCameraFrame() throws IOException {
        CamResponse configured = CamResponse.getDefaultInstance();
        publish(new Envelope(1, Direction.IN, Channel.NAO_CAMERA, CAMERA, Envelope.NO_ROBOT, "configured",
                configured, configured.toByteArray(), null));
        Envelope out = frame(jpeg(8, 8), 2, Origin.LIVE);
        publish(new Envelope(2, Direction.OUT, Channel.NAO_CAMERA, CAMERA, Envelope.NO_ROBOT, "frame",
                out.message(), out.raw(), null));
        publish(new Envelope(3, Direction.IN, Channel.NAO_RPC, CAMERA, Envelope.NO_ROBOT, "frame",
                out.message(), out.raw(), null));
        assertTrue(feed.latest().isEmpty());
        assertEquals("", feed.problem());
    }

    @Test
    void saysTheServersErrorAndAnUnreadableReplyUntilFramesFlowAgain() throws IOException {
        CamResponse error = CamResponse.newBuilder().setError("no camera").build();
        publish(new Envelope(1, Direction.IN, Channel.NAO_CAMERA, CAMERA, Envelope.NO_ROBOT, "error", error,
                error.toByteArray(), null));
        assertEquals("camera server: no camera", feed.problem());
        publish(new Envelope(2, Direction.IN, Channel.NAO_CAMERA, CAMERA, Envelope.NO_ROBOT, "malformed", null,
                new byte[]{(byte) 0xff, 1}, "truncated"));
        assertEquals("unreadable camera reply: truncated", feed.problem());
        publish(frame(jpeg(8, 8), 3, Origin.LIVE));
        assertEquals("", feed.problem());
    }

    @Test
    void measuresTheRateAndSizeOfTheFramesAsTheyArrive() throws IOException {
        byte[] jpeg = jpeg(16, 16);
        assertEquals(0, feed.framesPerSecond());
        for (int i = 0; i < 11; i++) {
            publish(frame(jpeg, i, Origin.LIVE));
            now.addAndGet(100_000); // 10 a second by this console's clock, whatever the envelopes' times
        }
        assertEquals(10.0, feed.framesPerSecond(), 0.5);
        assertEquals(jpeg.length, feed.bytesPerFrame(), 1e-9);
        now.addAndGet(NaoCameraFeed.STALE_MICROS);
        assertEquals(0, feed.framesPerSecond(), "no frame for 2 s: no rate");
    }

    @Test
    void showsTheReplaysFramesWhileOneIsOpenAndKeepsTheLiveOnesApart() throws IOException {
        byte[] live = jpeg(160, 120);
        byte[] replayed = jpeg(320, 240);
        publish(frame(live, 10, Origin.LIVE));
        publish(frame(replayed, 5, Origin.LIVE).asReplayed());
        assertArrayEquals(live, feed.latest().orElseThrow().jpeg());
        long liveSequence = feed.latest().orElseThrow().sequence();
        replaying.set(true);
        assertArrayEquals(replayed, feed.latest().orElseThrow().jpeg());
        assertNotEquals(liveSequence, feed.latest().orElseThrow().sequence(), "a view redraws on turning to the replay");
        feed.restartReplay();
        assertTrue(feed.latest().isEmpty(), "a jump of the replay starts its frames afresh");
        replaying.set(false);
        assertArrayEquals(live, feed.latest().orElseThrow().jpeg());
    }
}
