package touchline.transport.nao;

import com.google.protobuf.InvalidProtocolBufferException;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;
import touchline.proto.Nao.CamRequest;
import touchline.proto.Nao.CamResponse;
import touchline.protocol.nao.JpegHeader;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.MonotonicClock;

import java.net.InetSocketAddress;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The frames of one NAO camera server, fetched once and shared by every viewer.
 *
 * <p>Its thread ({@code nao-camera-HOST:PORT}) owns a JeroMQ REQ socket. While at least one
 * viewer holds a {@link #subscribe()} handle, it configures the server when the
 * {@link CameraSettings} changed (a CamRequest with fields set) and then fetches a frame with
 * an empty request at the configured rate; with no viewer it sends nothing. The newest frame
 * is kept in {@link #latestFrame()} for all viewers, who pull it at their own frame rate.
 * A request without reply within {@link #REPLY_TIMEOUT_MS} closes and reopens the socket
 * (Lazy Pirate: a REQ socket cannot send again before it got its reply) and configures
 * again, because a restarted server forgot its settings. Configure requests, replies and
 * frames are published into the Envelope stream ({@link Channel#NAO_CAMERA}); the empty
 * fetch requests are not, as they carry no information.
 */
public final class NaoCameraStream implements AutoCloseable {

    public static final int REPLY_TIMEOUT_MS = 1000;
    /** How long a stream whose camera link broke waits before it starts again. */
    static final int RESTART_BACKOFF_MS = 500;
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(NaoCameraStream.class);
    private static final int WINDOW = 30;

    private final NaoClientKeys keys;
    private final String host;
    private final int port;
    private final InetSocketAddress peer;
    private final NaoEnvelopeChannel envelopes;
    private final boolean ownsEnvelopes;
    private final MicrosClock wall;
    private final MonotonicClock monotonic;
    private final Object lock = new Object();
    private final Thread thread;
    private final AtomicLong fetched = new AtomicLong();
    private final AtomicLong errors = new AtomicLong();
    private volatile boolean running = true;
    private boolean started; // guarded by lock
    private final java.util.concurrent.CompletableFuture<Void> stopped = new java.util.concurrent.CompletableFuture<>();
    private volatile CameraFrame latest;
    private volatile String lastError;
    private volatile CameraSettings requested = CameraSettings.DEFAULT;
    private int subscribers; // guarded by lock

    // receive statistics over the last WINDOW frames, guarded by lock
    private final long[] frameNanos = new long[WINDOW];
    private final int[] frameBytes = new int[WINDOW];
    private int frameCount;

    /** As above with the console's clocks: {@code wall} stamps frames and envelopes, {@code monotonic} paces. */
    public NaoCameraStream(String host, int port, EnvelopeSink sink, NaoClientKeys keys, MicrosClock wall,
                           MonotonicClock monotonic) {
        this(host, port, new NaoEnvelopeChannel(sink), true, keys, wall, monotonic);
    }

    /** As above with the console's clocks: {@code wall} stamps frames and envelopes, {@code monotonic} paces. */
    public NaoCameraStream(String host, int port, NaoEnvelopeChannel envelopes, NaoClientKeys keys, MicrosClock wall,
                           MonotonicClock monotonic) {
        this(host, port, envelopes, false, keys, wall, monotonic);
    }

    private NaoCameraStream(String host, int port, NaoEnvelopeChannel envelopes, boolean owns, NaoClientKeys keys,
                            MicrosClock wall, MonotonicClock monotonic) {
        this.wall = wall;
        this.monotonic = monotonic;
        this.keys = keys;
        this.host = host;
        this.port = port;
        this.peer = InetSocketAddress.createUnresolved(host, port);
        this.envelopes = envelopes;
        this.ownsEnvelopes = owns;
        thread = new Thread(this::run, "nao-camera-" + host + ":" + port);
        thread.setDaemon(true);
        // The last word on what run() cannot go on from (out of memory): said, not only printed.
        thread.setUncaughtExceptionHandler((t, e) -> {
            fail("camera thread stopped: " + e);
            LOG.error("camera stream {}:{} stopped", host, port, e);
        });
    }

    /** Starts the camera thread; it fetches while someone {@link #subscribe subscribes}. */
    public NaoCameraStream start() {
        synchronized (lock) {
            if (!started && running) {
                started = true;
                thread.start();
            }
        }
        return this;
    }

    /** Starts fetching (if this is the first viewer) until the returned handle is closed. */
    public AutoCloseable subscribe() {
        synchronized (lock) {
            subscribers++;
            lock.notifyAll();
        }
        AtomicBoolean closed = new AtomicBoolean();
        return () -> {
            if (closed.compareAndSet(false, true)) {
                synchronized (lock) {
                    subscribers--;
                    lock.notifyAll();
                }
            }
        };
    }

    public int subscribers() {
        synchronized (lock) {
            return subscribers;
        }
    }

    /** Changes resolution, colour space or rate; the server is re-configured before the next frame. */
    public void configure(CameraSettings settings) {
        requested = settings;
        synchronized (lock) {
            lock.notifyAll();
        }
    }

    public CameraSettings settings() {
        return requested;
    }

    /** The newest frame, or null before the first one. */
    public CameraFrame latestFrame() {
        return latest;
    }

    /** The last error from the server or the link (e.g. "no reply within 1000 ms"), or null once frames flow. */
    public String lastError() {
        return lastError;
    }

    public long framesReceived() {
        return fetched.get();
    }

    public long errors() {
        return errors.get();
    }

    /** Frames per second over the last up to 30 frames, 0 when fewer than two arrived in the last 2 s. */
    public double measuredFps() {
        synchronized (lock) {
            int n = Math.min(frameCount, WINDOW);
            if (n < 2) {
                return 0;
            }
            long newest = frameNanos[(frameCount - 1) % WINDOW];
            long oldest = frameNanos[(frameCount - n) % WINDOW];
            if (monotonic.nanoTime() - newest > TimeUnit.SECONDS.toNanos(2) || newest == oldest) {
                return 0;
            }
            return (n - 1) * 1e9 / (newest - oldest);
        }
    }

    /** Mean JPEG size over the last up to 30 frames, 0 before the first. */
    public double bytesPerFrame() {
        synchronized (lock) {
            int n = Math.min(frameCount, WINDOW);
            long sum = 0;
            for (int i = 0; i < n; i++) {
                sum += frameBytes[i];
            }
            return n == 0 ? 0 : (double) sum / n;
        }
    }

    /**
     * Asks the camera thread to stop and returns at once (the window's thread may call it); the
     * thread lets go of its socket, then {@link #stopped()} completes.
     */
    @Override
    public void close() {
        boolean ends;
        synchronized (lock) {
            running = false;
            ends = !started;
            started = true; // never starts after a close
            lock.notifyAll();
        }
        if (ends) {
            ended();
        }
    }

    /** Completes once the camera thread has stopped after {@link #close()}. */
    public java.util.concurrent.CompletionStage<Void> stopped() {
        return stopped.minimalCompletionStage();
    }

    private void ended() {
        if (ownsEnvelopes) {
            envelopes.close();
        }
        stopped.complete(null);
    }

    // ---------------------------------------------------------------- camera thread

    /**
     * Fetches until closed. Whatever breaks the fetching (JeroMQ throws, or under {@code -ea}
     * fails one of its own assertions) is said in {@link #lastError()} and the stream starts
     * again on a fresh context after a back-off: the thread never ends before {@link #close()},
     * and never silently.
     */
    private void run() {
        try {
            fetchUntilClosed();
        } finally {
            ended();
        }
    }

    private void fetchUntilClosed() {
        while (running) {
            try (ZContext zmq = new ZContext(1)) {
                fetch(zmq);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            } catch (RuntimeException | AssertionError | LinkageError e) {
                fail("camera link failed (" + e + "); starting again");
                LOG.warn("camera stream {}:{} failed; starting again", host, port, e);
                try {
                    synchronized (lock) {
                        if (running) {
                            lock.wait(RESTART_BACKOFF_MS); // close() wakes it at once
                        }
                    }
                } catch (InterruptedException interrupted) {
                    Thread.currentThread().interrupt();
                    return;
                }
            }
        }
    }

    private void fetch(ZContext zmq) throws InterruptedException {
        ZMQ.Socket socket = open(zmq);
        CameraSettings configured = null;
        long nextFetch = monotonic.nanoTime();
        while (running) {
            CameraSettings want;
            synchronized (lock) {
                while (running && subscribers == 0) {
                    lock.wait();
                }
                want = requested;
                long now = monotonic.nanoTime();
                if (now < nextFetch) {
                    TimeUnit.NANOSECONDS.timedWait(lock, nextFetch - now);
                    continue;
                }
            }
            if (!running) {
                break;
            }
            boolean replied;
            if (!want.equals(configured)) {
                Reply r = exchange(socket, CamRequest.newBuilder().setResolution(want.resolution())
                        .setColorSpace(want.colorSpace()).setFps(want.fps()).build());
                replied = r != null;
                if (r != null && r.response != null && !r.response.hasError()) {
                    configured = want;
                    nextFetch = monotonic.nanoTime();
                } else {
                    nextFetch = monotonic.nanoTime() + TimeUnit.MILLISECONDS.toNanos(500); // back off
                }
            } else {
                long period = TimeUnit.SECONDS.toNanos(1) / want.fps();
                // Keep the average rate: a slightly late fetch is made up by the next slot;
                // only when more than a whole period behind do we restart the schedule.
                nextFetch += period;
                long now = monotonic.nanoTime();
                if (now - nextFetch > period) {
                    nextFetch = now;
                }
                Reply r = exchange(socket, null);
                replied = r != null;
                if (r != null && r.response != null) {
                    if (r.response.hasImageData() && !r.response.hasError()) {
                        frame(r, want);
                    } else {
                        configured = null; // e.g. a restarted server that was never configured
                    }
                }
            }
            if (!replied) {
                zmq.destroySocket(socket);
                socket = open(zmq);
                configured = null;
            }
        }
    }

    private ZMQ.Socket open(ZContext zmq) {
        ZMQ.Socket s = zmq.createSocket(SocketType.REQ);
        s.setLinger(0);
        s.setImmediate(false);
        s.setReceiveTimeOut(REPLY_TIMEOUT_MS);
        s.setSendTimeOut(REPLY_TIMEOUT_MS);
        s.setReconnectIVL(100);
        s.setReconnectIVLMax(1000);
        if (keys != null) {
            keys.applyTo(s);
        }
        s.connect("tcp://" + host + ":" + port);
        return s;
    }

    private record Reply(CamResponse response, byte[] raw) {
    }

    /** One request and its reply; null when there was no reply in time (the socket must be reopened). */
    private Reply exchange(ZMQ.Socket socket, CamRequest configure) {
        byte[] request = configure == null ? new byte[0] : configure.toByteArray();
        if (configure != null) {
            envelopes.publish(new Envelope(wall.nowMicros(), Direction.OUT, Channel.NAO_CAMERA, peer, Envelope.NO_ROBOT,
                    "configure", configure, request, null));
        }
        if (!socket.send(request, 0)) {
            fail("cannot send to the camera server (not connected)");
            return null;
        }
        byte[] raw = socket.recv(0);
        if (raw == null) {
            fail("no reply from the camera server within " + REPLY_TIMEOUT_MS + " ms" + (keys == null ? ""
                    : " (with CURVE keys: if the NAO runs, it may have refused our key; give it console.public"
                      + " — see docs/security.md)"));
            return null;
        }
        while (socket.hasReceiveMore()) {
            socket.recv(0); // a well-behaved server sends one frame; drop extras
        }
        CamResponse response;
        try {
            response = CamResponse.parseFrom(raw);
        } catch (InvalidProtocolBufferException e) {
            fail("unreadable CamResponse: " + e.getMessage());
            envelopes.publish(new Envelope(wall.nowMicros(), Direction.IN, Channel.NAO_CAMERA, peer, Envelope.NO_ROBOT,
                    "malformed", null, raw, e.getMessage()));
            return new Reply(null, raw);
        }
        if (response.hasError()) {
            fail("camera server: " + response.getError());
            envelopes.publish(new Envelope(wall.nowMicros(), Direction.IN, Channel.NAO_CAMERA, peer, Envelope.NO_ROBOT,
                    "error", response, raw, null));
        } else if (configure != null) {
            envelopes.publish(new Envelope(wall.nowMicros(), Direction.IN, Channel.NAO_CAMERA, peer, Envelope.NO_ROBOT,
                    "configured", response, raw, null));
        }
        return new Reply(response, raw);
    }

    private void frame(Reply r, CameraSettings settings) {
        byte[] jpeg = r.response.getImageData().toByteArray();
        int[] size = JpegHeader.size(jpeg);
        long now = monotonic.nanoTime();
        long sequence = fetched.incrementAndGet();
        latest = new CameraFrame(jpeg, size == null ? 0 : size[0], size == null ? 0 : size[1], sequence,
                wall.nowMicros(), settings);
        lastError = null;
        synchronized (lock) {
            frameNanos[frameCount % WINDOW] = now;
            frameBytes[frameCount % WINDOW] = jpeg.length;
            frameCount++;
        }
        envelopes.publish(new Envelope(wall.nowMicros(), Direction.IN, Channel.NAO_CAMERA, peer, Envelope.NO_ROBOT,
                "frame", r.response, r.raw, null));
    }

    private void fail(String why) {
        errors.incrementAndGet();
        lastError = why;
    }
}
