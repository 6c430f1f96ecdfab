package touchline.record;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
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
 * the thread runs a tick (the recorder's "write a chunk older than a second"). Written bytes
 * are handed to the disk itself ({@code fsync}) at most {@link #SYNC_MILLIS} after they were
 * written, so a power cut, not only a killed process, loses at most about a second.
 */
final class BackgroundFiles implements AutoCloseable {

    private static final long TICK_MILLIS = 100;
    static final long SYNC_MILLIS = 200;

    private sealed interface Job permits Write, CloseFile, Hold, Stop { }

    private record Write(FileChannel file, ByteBuffer bytes) implements Job { }

    private record CloseFile(FileChannel file) implements Job { }

    private record Hold(java.util.concurrent.CountDownLatch release) implements Job { }

    private record Stop() implements Job { }

    private static final int POOLED_BUFFERS = 16;

    private final BlockingQueue<Job> jobs = new LinkedBlockingQueue<>();
    // Direct buffers, reused: the copy into one is the only copy before the kernel's (a heap
    // array would be copied once more into a temporary direct buffer by the channel)
    private final BlockingQueue<ByteBuffer> free = new java.util.concurrent.ArrayBlockingQueue<>(POOLED_BUFFERS);
    private final AtomicLong pending = new AtomicLong();
    private final Runnable tick;
    private final Thread thread;
    private volatile String failure;
    private FileChannel unsynced;          // the file written since the last sync (file thread only)
    private long unsyncedSince;

    /**
     * Makes the queue; the file thread starts with {@link #start()} (writes queued before then wait).
     *
     * @param tick run on the file thread about every 100 ms while idle; may write through streams of this
     */
    BackgroundFiles(String threadName, Runnable tick) {
        this.tick = tick;
        this.thread = new Thread(this::run, threadName);
        thread.setDaemon(true);
    }

    /** Starts the file thread (once; later calls do nothing). */
    void start() {
        synchronized (thread) {
            if (thread.getState() == Thread.State.NEW) {
                thread.start();
            }
        }
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
                ByteBuffer copy = buffer(len);
                copy.put(b, off, len).flip();
                jobs.add(new Write(channel, copy));
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

    private ByteBuffer buffer(int len) {
        for (int i = free.size(); i > 0; i--) {
            ByteBuffer b = free.poll();
            if (b == null) {
                break;
            }
            if (b.capacity() >= len) {
                return b.clear();
            }
            free.offer(b); // too small for this one; keep it for the small writes
        }
        return ByteBuffer.allocateDirect(Math.max(64 * 1024, Integer.highestOneBit(Math.max(1, len - 1)) << 1));
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
            syncIfDue(job == null);
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
                int length = w.bytes().remaining();
                try {
                    if (failure == null) {
                        while (w.bytes().hasRemaining()) {
                            w.file().write(w.bytes());
                        }
                        if (unsynced != w.file()) {
                            sync();
                            unsynced = w.file();
                            unsyncedSince = System.nanoTime();
                        }
                    }
                } finally {
                    pending.addAndGet(-length);
                    free.offer(w.bytes()); // a full pool lets it go
                }
            } else if (job instanceof CloseFile c) {
                if (unsynced == c.file()) {
                    sync();
                }
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

    /** Syncs the written file when the thread is idle or the oldest unsynced write is {@link #SYNC_MILLIS} old. */
    private void syncIfDue(boolean idle) {
        if (unsynced != null && (idle || System.nanoTime() - unsyncedSince >= SYNC_MILLIS * 1_000_000L)) {
            try {
                sync();
            } catch (IOException e) {
                fail("recording stopped: " + e.getMessage());
            }
        }
    }

    private void sync() throws IOException {
        FileChannel file = unsynced;
        unsynced = null;
        if (file != null && file.isOpen()) {
            file.force(false);
        }
    }

    private void fail(String why) {
        if (failure == null) {
            failure = why;
        }
    }

    /**
     * Performs everything queued, closes the files it was asked to, and ends the thread (started
     * now if it never was, so nothing queued is lost).
     */
    @Override
    public void close() {
        start();
        jobs.add(new Stop());
        try {
            thread.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
