package touchline.record;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The recorder's disk side: one thread that performs every file write, in order, so the
 * threads that produce the bytes never wait for a disk. {@link #open} gives an
 * {@code OutputStream} whose writes copy the bytes and queue them (a writer writes whole
 * chunks, so this is one copy per chunk, not per message); {@link #pendingBytes} says how
 * much is queued, so a producer can refuse work when the disk falls behind. Between writes
 * the thread runs a tick (the recorder's "write a chunk older than a second").
 */
final class BackgroundFiles implements AutoCloseable {

    private static final long TICK_MILLIS = 100;

    private sealed interface Job permits Write, CloseFile, Hold, Stop { }

    private record Write(FileChannel file, byte[] bytes) implements Job { }

    private record CloseFile(FileChannel file) implements Job { }

    private record Hold(java.util.concurrent.CountDownLatch release) implements Job { }

    private record Stop() implements Job { }

    private final BlockingQueue<Job> jobs = new LinkedBlockingQueue<>();
    private final AtomicLong pending = new AtomicLong();
    private final Runnable tick;
    private final Thread thread;
    private volatile String failure;

    /** @param tick run on the file thread about every 100 ms while idle; may write through streams of this */
    BackgroundFiles(String threadName, Runnable tick) {
        this.tick = tick;
        this.thread = new Thread(this::run, threadName);
        thread.setDaemon(true);
        thread.start();
    }

    /** Creates (or truncates) {@code file} now, on the calling thread, so a bad path fails at once. */
    OutputStream open(Path file) throws IOException {
        FileChannel channel = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING,
                StandardOpenOption.WRITE);
        return new OutputStream() {
            @Override
            public void write(int b) {
                write(new byte[]{(byte) b}, 0, 1);
            }

            @Override
            public void write(byte[] b, int off, int len) {
                if (len == 0) {
                    return;
                }
                pending.addAndGet(len);
                jobs.add(new Write(channel, Arrays.copyOfRange(b, off, off + len)));
            }

            @Override
            public void close() {
                jobs.add(new CloseFile(channel));
            }
        };
    }

    /** Test hook: the thread stops at this point of the queue until {@code release} opens. */
    void hold(java.util.concurrent.CountDownLatch release) {
        jobs.add(new Hold(release));
    }

    /** Bytes handed over but not yet written. */
    long pendingBytes() {
        return pending.get();
    }

    /** Why writing stopped (the first I/O error), or null. */
    String failure() {
        return failure;
    }

    private void run() {
        long lastTick = System.nanoTime();
        while (true) {
            Job job;
            try {
                job = jobs.poll(TICK_MILLIS, TimeUnit.MILLISECONDS);
            } catch (InterruptedException e) {
                return;
            }
            if (job instanceof Stop) {
                return;
            }
            if (job != null) {
                perform(job);
            }
            if (job == null || System.nanoTime() - lastTick > TICK_MILLIS * 1_000_000L) {
                lastTick = System.nanoTime();
                try {
                    tick.run();
                } catch (RuntimeException e) {
                    fail("recording stopped: " + e.getMessage());
                }
            }
        }
    }

    private void perform(Job job) {
        try {
            if (job instanceof Write w) {
                try {
                    if (failure == null) {
                        ByteBuffer buf = ByteBuffer.wrap(w.bytes());
                        while (buf.hasRemaining()) {
                            w.file().write(buf);
                        }
                    }
                } finally {
                    pending.addAndGet(-w.bytes().length);
                }
            } else if (job instanceof CloseFile c) {
                c.file().close();
            } else if (job instanceof Hold h) {
                h.release().await();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException e) {
            fail("recording stopped: " + e.getMessage());
        }
    }

    private void fail(String why) {
        if (failure == null) {
            failure = why;
        }
    }

    /** Performs everything queued, closes the files it was asked to, and ends the thread. */
    @Override
    public void close() {
        jobs.add(new Stop());
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
