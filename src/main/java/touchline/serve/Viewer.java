package touchline.serve;

import io.netty.channel.Channel;

import java.net.SocketAddress;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.LongAdder;

/**
 * One connected viewer (Foxglove, Lichtblick, a script): its subscriptions and the messages
 * waiting for its network. Publishers only queue ({@link #offer}) and never wait; the
 * viewer's event loop sends while the socket is writable and stops when it is not, so a slow
 * viewer gets the newest message of each channel once it catches up, and nobody else waits.
 */
final class Viewer {

    private final Channel channel;
    private final FoxgloveFrames frames;
    private final PendingMessages pending;
    private final AtomicBoolean drainScheduled = new AtomicBoolean();
    private final Map<Integer, Subscription> subscriptions = new ConcurrentHashMap<>();
    /** The same subscriptions by channel: one per channel, found without a search through all of them. */
    private final Map<ServedChannel, Subscription> byChannel = new ConcurrentHashMap<>();
    private final LongAdder sent = new LongAdder();
    private final LongAdder statusesDropped = new LongAdder();

    /**
     * The query parameter ({@code ?raw=1}) by which a viewer asks for the channels of bytes too:
     * another Touchline does; Foxglove and Lichtblick, which have no schema for them and would
     * list each as a channel they failed to parse, do not.
     */
    static final String BYTES_PARAMETER = "raw";

    private final boolean takesBytes;
    private final boolean webPage;

    Viewer(Channel channel, FoxgloveFrames frames, int queueLimit, boolean takesBytes) {
        this(channel, frames, queueLimit, takesBytes, false);
    }

    /** {@code webPage}: the upgrade came with an {@code Origin} (a page in a browser, not a tool). */
    Viewer(Channel channel, FoxgloveFrames frames, int queueLimit, boolean takesBytes, boolean webPage) {
        this.channel = channel;
        this.frames = frames;
        this.pending = new PendingMessages(queueLimit);
        this.takesBytes = takesBytes;
        this.webPage = webPage;
    }

    /** Whether a web page in a browser opened this connection (its upgrade named an origin). */
    boolean webPage() {
        return webPage;
    }

    /** Whether this viewer hears of {@code c} at all. */
    boolean wants(ServedChannel c) {
        return takesBytes || !c.bytes();
    }

    SocketAddress address() {
        return channel.remoteAddress();
    }

    /**
     * The least time between two writes to a viewer: what arrives meanwhile leaves in one write,
     * so one system call (and, on loopback, one wake-up of the viewer) per viewer per interval
     * instead of one per message. At the UI benchmark's load (2 430 messages/s to eight viewers)
     * sending each at once cost the window a third of its frame rate (docs/benchmarks.md, issue
     * 16). A message after a quiet spell leaves at once; under load one waits at most this long,
     * a fifth of the 50 ms latency budget.
     */
    static final long SEND_INTERVAL_MILLIS = 10;

    /** Event loop: a write happened less than {@link #SEND_INTERVAL_MILLIS} ago; its end drains what waits. */
    private boolean coolingDown;

    /**
     * From any thread: queues a message for {@code s}; the event loop sends it at once, or after
     * the last write's {@link #SEND_INTERVAL_MILLIS} with whatever else arrives meanwhile. Never
     * blocks.
     */
    void offer(Subscription s, long timeNanos, byte[] payload) {
        pending.offer(s, timeNanos, payload, !channel.isWritable());
        if (drainScheduled.compareAndSet(false, true)) {
            try {
                channel.eventLoop().execute(this::drainUnlessCoolingDown);
            } catch (RejectedExecutionException e) {
                drainScheduled.set(false); // the server is closing
            }
        }
    }

    /** Event loop: drains now, or leaves it to the end of the interval since the last write. */
    private void drainUnlessCoolingDown() {
        if (!coolingDown) {
            drain();
        }
    }

    /** Event loop: the interval since the last write is over; what arrived meanwhile goes now. */
    private void coolDownOver() {
        coolingDown = false;
        if (drainScheduled.get()) {
            drain();
        }
    }

    /** On the event loop: sends pending messages while the socket takes them. */
    void drain() {
        drainScheduled.set(false);
        boolean wrote = false;
        while (channel.isActive() && channel.isWritable()) {
            PendingMessages.Pending p = pending.poll();
            if (p == null) {
                break;
            }
            if (!p.subscription.active()) {
                continue;
            }
            channel.write(frames.messageData(channel.alloc(), p.subscription.id(), p.timeNanos, p.payload),
                    channel.voidPromise());
            sent.increment();
            wrote = true;
        }
        if (wrote) {
            channel.flush();
            if (!coolingDown) {
                coolingDown = true;
                try {
                    channel.eventLoop().schedule(this::coolDownOver, SEND_INTERVAL_MILLIS,
                            java.util.concurrent.TimeUnit.MILLISECONDS);
                } catch (RejectedExecutionException e) {
                    coolingDown = false; // the server is closing
                }
            }
        }
    }

    /**
     * Subscribes under the viewer's {@code id} and sends a state channel's value as it was when
     * the subscription joined, so a viewer need not wait for a change (a console state, which
     * holds now, is stamped {@code nowNanos}); the reason when refused.
     */
    Optional<String> subscribe(int id, ServedChannel c, long nowNanos) {
        if (!wants(c)) {
            return Optional.of("unknown channel " + c.id());
        }
        if (subscriptions.containsKey(id)) {
            return Optional.of("subscription id " + id + " is in use");
        }
        Subscription already = byChannel.get(c);
        if (already != null) {
            return Optional.of("already subscribed to channel " + c.id() + " (subscription " + already.id() + ")");
        }
        Subscription s = new Subscription(this, id, c);
        subscriptions.put(id, s);
        byChannel.put(c, s);
        ServedChannel.Latched then = c.add(s);
        if (then.value() != null) {
            offer(s, then.timeNanos() > 0 ? then.timeNanos() : nowNanos, then.value());
        }
        return Optional.empty();
    }

    /** Ends subscription {@code id}; the reason when there is none. */
    Optional<String> unsubscribe(int id) {
        Subscription s = subscriptions.remove(id);
        if (s == null) {
            return Optional.of("no subscription " + id);
        }
        byChannel.remove(s.channel());
        s.end();
        return Optional.empty();
    }

    /** Ends every subscription (the viewer left). */
    void leave() {
        List.copyOf(subscriptions.values()).forEach(s -> {
            subscriptions.remove(s.id());
            byChannel.remove(s.channel());
            s.end();
        });
    }

    /** The server info and every channel known so far: what a viewer hears first. */
    void welcome(List<ServedChannel> channels) {
        channel.write(frames.serverInfo(), channel.voidPromise());
        channel.writeAndFlush(frames.advertise(channels.stream().filter(this::wants).toList()), channel.voidPromise());
    }

    /** New channels; sent even to a viewer that is behind, or it could never subscribe to them. */
    void advertise(List<ServedChannel> channels) {
        List<ServedChannel> wanted = channels.stream().filter(this::wants).toList();
        if (!wanted.isEmpty()) {
            channel.writeAndFlush(frames.advertise(wanted), channel.voidPromise());
        }
    }

    /** A status message, unless the viewer is not reading (then it is counted, never queued). */
    void status(int level, String message) {
        if (channel.isWritable()) {
            channel.writeAndFlush(frames.status(level, message), channel.voidPromise());
        } else {
            statusesDropped.increment();
        }
    }

    /** The answer to the viewer's request {@code id}, unless the viewer is not reading (then counted, never queued). */
    void answer(int level, String message, String id) {
        if (channel.isWritable()) {
            channel.writeAndFlush(frames.status(level, message, id), channel.voidPromise());
        } else {
            statusesDropped.increment();
        }
    }

    /** Whether the viewer connected from this machine (a loopback address). */
    boolean local() {
        return address() instanceof java.net.InetSocketAddress i && i.getAddress() != null
                && i.getAddress().isLoopbackAddress();
    }

    /** The server time, when the viewer keeps up. */
    void time(long timeNanos) {
        if (channel.isActive() && channel.isWritable()) {
            channel.writeAndFlush(frames.time(channel.alloc(), timeNanos), channel.voidPromise());
        }
    }

    ViewerInfo info() {
        java.net.SocketAddress a = address();
        String where = a instanceof java.net.InetSocketAddress i ? i.getAddress().getHostAddress() + ":" + i.getPort()
                : String.valueOf(a);
        List<String> topics = subscriptions.values().stream().map(s -> s.channel().topic()).sorted().toList();
        return new ViewerInfo(where, topics, sent(), dropped());
    }

    int subscriptionCount() {
        return subscriptions.size();
    }

    long sent() {
        return sent.sum();
    }

    long dropped() {
        return pending.dropped();
    }

    Channel channel() {
        return channel;
    }
}
