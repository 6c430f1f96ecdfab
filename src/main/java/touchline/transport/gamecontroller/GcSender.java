package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.DatagramChannel;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Sends the game state every 500 ms on a fixed, drift-free grid (deadline k·interval from the
 * start, not "sleep after send" like the Java GameController) and at once when
 * {@link #sendNow()} is called after a state change, without shifting the grid; or, for the HSL
 * formats, on the official HSL schedule, where only a switch to stopped sends at once, followed
 * by four more datagrams 200 ms apart ({@link SendSchedule}, told by {@link #changed}). Every cycle
 * sends one datagram per format (e.g. v8 plus the v7 compatibility packet) to every
 * destination; packetNumber starts at 0 and wraps 255→0. Each datagram is published as an
 * OUT envelope.
 */
public final class GcSender implements AutoCloseable {

    /** What to send; {@code periodic} is false for an immediate send after a change. */
    @FunctionalInterface
    public interface Source {
        GameControlData next(boolean periodic);

        /**
         * The cycle's datagrams went out (on the sender's thread): the place for work that must
         * not delay them, such as handing the true state to monitors.
         */
        default void sent(boolean periodic) {
        }
    }

    /** Spacing of the HSL burst after play gets stopped. */
    public static final long BURST_SPACING_MS = 200;

    private static final Logger LOG = LoggerFactory.getLogger(GcSender.class);
    /** The last stretch before a deadline is waited out by spinning: parkNanos can overshoot. */
    private static final long SPIN_NANOS = 300_000;

    private final Source source;
    private final List<GameStateFormat> formats;
    private final List<InetSocketAddress> destinations;
    private final EnvelopeSink sink;
    private final long intervalNanos;
    private final boolean burstOnStop;
    /** Guarded by {@link #scheduleLock}; created when the sender thread starts. */
    private SendSchedule schedule;
    private final Object scheduleLock = new Object();
    private final DatagramChannel channel;
    private final AtomicBoolean wake = new AtomicBoolean();
    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong sendErrors = new AtomicLong();
    private volatile boolean running;
    private volatile boolean realtime;
    /** {@link #realtimeOutcome()} when real-time priority was not asked for. */
    public static final String NOT_REQUESTED = "not requested";
    /** {@link #realtimeOutcome()} before the sender thread has asked. */
    public static final String NOT_STARTED = "not started yet";

    private final java.util.concurrent.CompletableFuture<String> realtimeOutcome =
            new java.util.concurrent.CompletableFuture<>();
    private volatile Thread thread;
    private int packetNumber;
    private final touchline.transport.MicrosClock stamps;
    private String lastError;

    /**
     * @param source       game state supplier
     * @param formats      formats sent each cycle (the first carries the packet number)
     * @param destinations broadcast or unicast addresses (port 3838 in a real game)
     * @param bind         local address to send from (null: any address, ephemeral port)
     * @param sink         receives one OUT envelope per datagram
     * @param intervalMs   send period (500 in a game)
     * @param stamps       the console's clock, for the envelopes' time
     */
    public GcSender(Source source, List<GameStateFormat> formats, List<InetSocketAddress> destinations,
                    InetSocketAddress bind, EnvelopeSink sink, long intervalMs, touchline.transport.MicrosClock stamps)
            throws IOException {
        this(source, formats, destinations, bind, sink, intervalMs, false, stamps);
    }

    /**
     * @param burstOnStop the HSL schedule: no datagram at once after a change, except the burst
     *                    when play gets stopped ({@link #changed})
     */
    public GcSender(Source source, List<GameStateFormat> formats, List<InetSocketAddress> destinations,
                    InetSocketAddress bind, EnvelopeSink sink, long intervalMs, boolean burstOnStop,
                    touchline.transport.MicrosClock stamps) throws IOException {
        this.burstOnStop = burstOnStop;
        this.stamps = stamps;
        if (formats.isEmpty() || destinations.isEmpty()) {
            throw new IllegalArgumentException("need at least one format and one destination");
        }
        this.source = source;
        this.formats = List.copyOf(formats);
        this.destinations = List.copyOf(destinations);
        this.sink = sink;
        this.intervalNanos = intervalMs * 1_000_000L;
        this.channel = DatagramChannel.open();
        channel.setOption(StandardSocketOptions.SO_BROADCAST, true);
        channel.bind(bind == null ? new InetSocketAddress(0) : bind);
    }

    public InetSocketAddress localAddress() throws IOException {
        return (InetSocketAddress) channel.getLocalAddress();
    }

    /** Asks for SCHED_RR on the sender thread when it starts (Linux, needs CAP_SYS_NICE). */
    public void useRealtimePriority(boolean on) {
        realtime = on;
    }

    /**
     * "" when the sender thread got real-time priority, else why not ({@link #NOT_REQUESTED},
     * {@link #NOT_STARTED}, or the system's refusal).
     */
    public String realtimeOutcome() {
        return realtimeOutcome.getNow(NOT_STARTED);
    }

    /** {@link #realtimeOutcome()} once the started sender thread has asked (at most {@code timeoutMs}). */
    public String awaitRealtimeOutcome(long timeoutMs) {
        try {
            return realtimeOutcome.get(timeoutMs, java.util.concurrent.TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.TimeoutException | java.util.concurrent.ExecutionException e) {
            return realtimeOutcome();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return realtimeOutcome();
        }
    }

    public synchronized void start() {
        if (thread != null) {
            return;
        }
        running = true;
        thread = new Thread(this::loop, "gc-sender");
        thread.setDaemon(true);
        thread.setPriority(Thread.MAX_PRIORITY);
        thread.start();
    }

    /**
     * The game changed; {@code stopped} is whether the state robots get now has play stopped.
     * Older formats send at once; the HSL schedule only when this is the switch to stopped.
     */
    public void changed(boolean stopped) {
        boolean extra;
        synchronized (scheduleLock) {
            extra = schedule == null ? !burstOnStop : schedule.changed(System.nanoTime(), stopped);
        }
        if (extra) {
            sendNow();
        } else {
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t); // the schedule may have moved the next datagram to now
            }
        }
    }

    /** Sends the current state as soon as possible (after a state change). */
    public void sendNow() {
        wake.set(true);
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
        }
    }

    public long packetsSent() {
        return sent.get();
    }

    public long sendErrors() {
        return sendErrors.get();
    }

    private void loop() {
        realtimeOutcome.complete(realtime ? new RealtimePriority(10).applyToCurrentThread() : NOT_REQUESTED);
        long start = System.nanoTime();
        synchronized (scheduleLock) {
            schedule = burstOnStop ? SendSchedule.burstOnStop(start, intervalNanos, BURST_SPACING_MS * 1_000_000L)
                    : SendSchedule.everyChange(start, intervalNanos);
        }
        while (running) {
            long now = System.nanoTime();
            long next;
            synchronized (scheduleLock) {
                next = schedule.next();
            }
            boolean periodic = now - next >= 0;
            if (periodic || wake.get()) {
                sendCycle(periodic);
                if (periodic) {
                    synchronized (scheduleLock) {
                        schedule.sent(next, System.nanoTime());
                    }
                }
                continue;
            }
            long wait = next - now;
            if (wait > SPIN_NANOS) {
                LockSupport.parkNanos(this, wait - SPIN_NANOS);
            } else {
                Thread.onSpinWait();
            }
        }
    }

    private void sendCycle(boolean periodic) {
        GameControlData data;
        try {
            data = source.next(periodic);
        } catch (RuntimeException e) {
            LOG.error("game state source failed; nothing sent this cycle", e);
            wake.set(false);
            return;
        }
        // Cleared after reading the state: a change during next() is already in this packet.
        wake.set(false);
        GameControlData numbered = data.withPacketNumber(packetNumber);
        for (GameStateFormat f : formats) {
            byte[] bytes = f.encode(numbered);
            for (InetSocketAddress dest : destinations) {
                sendOne(f, bytes, dest);
            }
        }
        packetNumber = (packetNumber + 1) & 0xFF;
        try {
            source.sent(periodic);
        } catch (RuntimeException e) {
            LOG.error("after-send work of the game state source failed", e);
        }
    }

    private void sendOne(GameStateFormat f, byte[] bytes, InetSocketAddress dest) {
        try {
            channel.send(ByteBuffer.wrap(bytes), dest);
            sent.incrementAndGet();
            sink.accept(new Envelope(stamps.nowMicros(), Direction.OUT, Channel.GAMECONTROLLER, dest, Envelope.NO_ROBOT,
                    f.kind(), null, bytes, null));
        } catch (IOException e) {
            sendErrors.incrementAndGet();
            String msg = dest + ": " + e.getMessage();
            if (!msg.equals(lastError)) {
                lastError = msg;
                LOG.warn("GameController packet not sent to {}", msg);
            }
        }
    }

    @Override
    public void close() {
        running = false;
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
            try {
                t.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        try {
            channel.close();
        } catch (IOException ignored) {
            // closing a datagram channel cannot lose data
        }
    }
}
