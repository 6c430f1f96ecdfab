package touchline.transport.nao;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.testing.Await;
import touchline.transport.Channel;
import touchline.transport.Envelope;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadInfo;
import java.lang.management.ThreadMXBean;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The camera stream against the in-test camera stand-in (the real server: NaoLinkRobotSideIT). */
@Tag("slow")
class NaoCameraStreamTest {

    @Test
    void fetchesOnlyWhileSubscribedSharesOneFrameAndReconfigures() throws Exception {
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        try (FakeNaoCamera camera = new FakeNaoCamera();
             NaoCameraStream stream = new NaoCameraStream("127.0.0.1", camera.port(), envelopes::add, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            stream.configure(new CameraSettings(1, 11, 30));
            awaitWaitingForAViewer(camera.port());
            assertEquals(0, camera.fetches.get(), "nothing fetched without a viewer");
            assertEquals(0, camera.configures.get(), "nothing configured without a viewer");
            assertNull(stream.latestFrame());

            AutoCloseable first = stream.subscribe();
            AutoCloseable second = stream.subscribe();
            assertTrue(Poll.until(() -> stream.framesReceived() >= 10));
            CameraFrame frame = stream.latestFrame();
            assertEquals(320, frame.width());
            assertEquals(240, frame.height());
            assertTrue(stream.measuredFps() > 5, "fps " + stream.measuredFps());
            assertTrue(stream.bytesPerFrame() > 100);

            stream.configure(new CameraSettings(0, 11, 30));
            assertTrue(Poll.until(() -> stream.latestFrame().width() == 160));
            assertEquals(2, camera.configures.get());

            first.close();
            first.close(); // closing twice must not count twice
            assertEquals(1, stream.subscribers());
            second.close();
            assertEquals(0, stream.subscribers());
            awaitWaitingForAViewer(camera.port()); // an exchange in progress ends, and then no other starts
            assertTrue(envelopes.stream().anyMatch(e -> e.channel() == Channel.NAO_CAMERA && e.kind().equals("frame")));
            assertTrue(envelopes.stream().anyMatch(e -> e.channel() == Channel.NAO_CAMERA && e.kind().equals("configure")));
        }
    }

    /**
     * Waits until the stream's thread waits for a subscriber: parked (no timeout) on its lock inside
     * {@code fetch} with none subscribed, where it sends nothing until {@code subscribe()} wakes it.
     * State and stack are one {@link ThreadInfo}, taken together.
     */
    private static void awaitWaitingForAViewer(int port) throws InterruptedException {
        String name = "nao-camera-127.0.0.1:" + port;
        Await.until(name + " waiting for a viewer", () -> {
            ThreadMXBean threads = ManagementFactory.getThreadMXBean();
            for (ThreadInfo t : threads.getThreadInfo(threads.getAllThreadIds(), Integer.MAX_VALUE)) {
                if (t != null && t.getThreadName().equals(name)) {
                    return t.getThreadState() == Thread.State.WAITING && parkedInFetch(t.getStackTrace());
                }
            }
            return false;
        });
    }

    private static boolean parkedInFetch(StackTraceElement[] stack) {
        int i = 0;
        while (i < stack.length && stack[i].getClassName().equals(Object.class.getName())) {
            i++; // Object.wait (and wait0 on newer JDKs)
        }
        return i > 0 && i < stack.length && stack[i].getClassName().equals(NaoCameraStream.class.getName())
                && stack[i].getMethodName().equals("fetch");
    }

    @Test
    void framesAndEnvelopesAreStampedByTheWallClockTheStreamIsHanded() throws Exception {
        long wallMicros = 1_790_000_000_000_000L;
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        try (FakeNaoCamera camera = new FakeNaoCamera();
             NaoCameraStream stream = new NaoCameraStream("127.0.0.1", camera.port(), envelopes::add, null,
                     () -> wallMicros, System::nanoTime).start();
             AutoCloseable viewer = stream.subscribe()) {
            assertTrue(Poll.until(() -> stream.framesReceived() >= 2));
            assertEquals(wallMicros, stream.latestFrame().receiveTimeMicros());
            assertTrue(envelopes.stream().anyMatch(e -> e.kind().equals("frame")));
            assertTrue(envelopes.stream().allMatch(e -> e.timeMicros() == wallMicros));
        }
    }

    @Test
    void anAbsentServerIsAnErrorNotACrash() throws Exception {
        int port;
        try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
            port = s.getLocalPort();
        }
        try (NaoCameraStream stream = new NaoCameraStream("127.0.0.1", port, e -> { }, null, new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            AutoCloseable viewer = stream.subscribe();
            assertTrue(Poll.until(() -> stream.lastError() != null));
            viewer.close();
        }
    }

    @Test
    void unknownSettingsAreRejectedBeforeTheyTravel() {
        assertThrows(IllegalArgumentException.class, () -> new CameraSettings(9, 11, 15));
        assertThrows(IllegalArgumentException.class, () -> new CameraSettings(2, 5, 15));
        assertThrows(IllegalArgumentException.class, () -> new CameraSettings(2, 11, 0));
    }
}
