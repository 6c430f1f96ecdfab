package touchline.record;

import java.util.concurrent.CountDownLatch;

/**
 * For tests outside this package: holds a recorder's disk thread where it stands in its queue
 * (nothing more is written, and finishing the file waits) until released or closed.
 */
public final class HeldDisk implements AutoCloseable {

    private final CountDownLatch release = new CountDownLatch(1);

    public HeldDisk(Recorder recorder) {
        recorder.holdDisk(release);
    }

    public void release() {
        release.countDown();
    }

    @Override
    public void close() {
        release();
    }
}
