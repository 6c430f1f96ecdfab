package touchline.transport.nao;

import touchline.proto.Nao.HAWActorRPCRequest;
import touchline.transport.MicrosClock;
import touchline.transport.MonotonicClock;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;

/**
 * What a NAO link does with its calls, one {@link #turn} at a time: take the calls submitted
 * since the last turn, read the connection's events and the robot's replies, and act on time
 * (attempt deadlines and retries, calls waiting for the connection, paced calls now due). A
 * call goes out at once when the link is {@link ConnectionState#ONLINE} and its method's
 * interval allows, waits while the link first connects, and ends as lost when the link is
 * lost, refused or closed. Time comes from the injected monotonic clock, so a test drives the
 * dispatcher turn by turn on a fake clock and a fake {@link LinkWire}, without a thread. Not
 * thread-safe: the link's lock guards it ({@link LinkLoop}); only {@link #queue} and the
 * counters may be used from any thread.
 *
 * <p>Liveness: the ZMTP handshake, not the TCP connect, makes the state
 * {@link ConnectionState#ONLINE}; a disconnect or heartbeat timeout makes it
 * {@link ConnectionState#LOST}: every pending, waiting or paced call then ends as
 * {@link CallOutcome.Lost} and the wire is reopened, so nothing queued can run when the robot
 * comes back. While LOST new calls fail at once; while first CONNECTING they wait for ONLINE
 * within their timeout. Every request carries {@code deadlineMillis} (wall-clock now + what is
 * left of its timeout) so the robot drops it when late.
 *
 * <p>Rules from {@link NaoLinkConfig}: per-method timeouts; retries (a resend under a new id at
 * the attempt's deadline) only for idempotent methods; per-method minimum intervals
 * ({@link CallPacing}).
 */
final class CallDispatcher {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(CallDispatcher.class);
    /** The longest a link waits between two turns when no timer is due earlier. */
    static final long IDLE_TURN_NANOS = TimeUnit.MILLISECONDS.toNanos(200);

    private final String peer;
    private final NaoLinkConfig config;
    private final LinkWire wire;
    private final ConnectionWatch watch;
    private final LinkTraffic traffic;
    private final MonotonicClock clock;
    private final MicrosClock wallClock;
    private final ConcurrentLinkedQueue<QueuedCall> submissions = new ConcurrentLinkedQueue<>();
    private final List<Consumer<ConnectionState>> stateListeners = new CopyOnWriteArrayList<>();
    private final LinkCounters counters = new LinkCounters();
    private final ReplyReader replies = new ReplyReader();
    private final PendingCalls pending = new PendingCalls();
    private final CallPacing pacing;
    private final List<QueuedCall> awaitingOnline = new ArrayList<>();

    /**
     * @param peer      "host:port", for the texts
     * @param wallClock the console's wall clock: the robot drops a request past its {@code deadlineMillis}
     */
    CallDispatcher(String peer, NaoLinkConfig config, LinkWire wire, ConnectionWatch watch, LinkTraffic traffic,
                   MonotonicClock clock, MicrosClock wallClock) {
        this.peer = peer;
        this.config = config;
        this.wire = wire;
        this.watch = watch;
        this.traffic = traffic;
        this.clock = clock;
        this.wallClock = wallClock;
        this.pacing = new CallPacing(config);
    }

    /** Queues a call for the next turn (or the next {@link #drainSubmissions}). Any thread. */
    void queue(QueuedCall call) {
        submissions.add(call);
    }

    /** Told of each change of the connection's state, on the thread that makes the turn; must not block. */
    AutoCloseable onStateChange(Consumer<ConnectionState> listener) {
        stateListeners.add(listener);
        return () -> stateListeners.remove(listener);
    }

    /**
     * One turn: connection events, replies, submitted calls, timers, in that order. Returns when
     * the next turn is due at the latest (monotonic nanoseconds).
     */
    long turn() {
        // Read both sockets on every turn, not only when a selector flagged them: JeroMQ was
        // seen to miss a monitor event's signal.
        readEvents();
        readReplies();
        drainSubmissions();
        long now = clock.nanoTime();
        runTimers(now);
        return nextTurnNanos(now);
    }

    /** Dispatches the queued calls, oldest first. */
    void drainSubmissions() {
        QueuedCall s;
        while ((s = submissions.poll()) != null) {
            dispatch(s);
        }
    }

    /** Sends {@code s} now, or holds it (pacing, connecting), or ends it (no connection). */
    void dispatch(QueuedCall s) {
        if (s.future().isDone()) {
            return;
        }
        ConnectionState state = watch.state();
        if (state == ConnectionState.LOST || state == ConnectionState.CLOSED) {
            lose(s, "robot not connected");
            return;
        }
        if (state == ConnectionState.REFUSED) {
            lose(s, watch.securityProblem());
            return;
        }
        if (pacing.holdIfEarly(s, clock.nanoTime())) {
            return;
        }
        if (state == ConnectionState.CONNECTING) {
            awaitingOnline.add(s);
            return;
        }
        send(s, 1);
    }

    /** When the next turn must run at the latest, seen at {@code now}: the earliest timer, or an idle turn. */
    long nextTurnNanos(long now) {
        long next = pending.nextDeadline(now + IDLE_TURN_NANOS);
        for (QueuedCall s : awaitingOnline) {
            next = Math.min(next, s.deadlineNanos());
        }
        return pacing.nextDue(next);
    }

    /** The link ends: every call pending, waiting or queued ends as lost with {@code why}. */
    void endCalls(String why) {
        CallOutcome.Lost outcome = new CallOutcome.Lost(why);
        failAll(outcome);
        QueuedCall s;
        while ((s = submissions.poll()) != null) {
            s.end(outcome);
        }
    }

    /** The link ended (after {@link #endCalls}): the state becomes closed. */
    void closed(String why) {
        apply(watch.closed(why));
    }

    NaoLink.LinkStats stats() {
        return counters.stats(pending, pacing, replies);
    }

    private void send(QueuedCall s, int attempt) {
        long now = clock.nanoTime();
        long remaining = s.idempotent() ? s.timeoutMillis()
                : Math.max(1, TimeUnit.NANOSECONDS.toMillis(s.deadlineNanos() - now));
        HAWActorRPCRequest request = s.request().setDeadlineMillis(wallClock.nowMicros() / 1000 + remaining).build();
        byte[] payload = request.toByteArray();
        long id = pending.nextId();
        if (!wire.send(id, payload)) {
            // With immediate=1 semantics there is no pipe without a live peer: nothing was queued.
            lose(s, "no connection to send on");
            return;
        }
        counters.sent();
        pacing.sent(s.call(), now);
        pending.sent(id, s, now + TimeUnit.MILLISECONDS.toNanos(remaining), attempt);
        traffic.request(s.call(), request, payload);
    }

    private void readReplies() {
        List<byte[]> frames;
        while ((frames = wire.receive()) != null) {
            handleReply(frames);
        }
    }

    private void handleReply(List<byte[]> frames) {
        byte[] payload = frames.get(frames.size() - 1);
        ReplyReader.Read read = replies.read(frames);
        if (read instanceof ReplyReader.Malformed m) {
            traffic.malformed(payload, m.why());
            PendingCalls.Sent p = m.id() < 0 ? null : pending.unreadable(m.id());
            if (p != null) {
                p.call().end(new CallOutcome.Failed(m.callError()));
            }
            return;
        }
        ReplyReader.Reply reply = (ReplyReader.Reply) read;
        PendingCalls.Sent p = pending.answered(reply.id());
        traffic.reply(p == null ? "stray" : p.call().call().qualifiedName(), reply.response(), payload);
        if (p == null) {
            return;
        }
        counters.answered();
        watch.replied();
        p.call().end(replies.outcomeOf(reply.response()));
    }

    private void readEvents() {
        NaoConnection.Event event;
        while ((event = wire.nextEvent()) != null) {
            List<ConnectionWatch.Transition> changes = watch.onEvent(event, clock.nanoTime());
            apply(changes);
            if (changes.stream().anyMatch(t -> t.to() == ConnectionState.LOST)) {
                return; // the monitor socket was replaced
            }
        }
    }

    /** Acts on state changes: announces each; online sends the waiting calls, lost and refused end every call. */
    private void apply(List<ConnectionWatch.Transition> changes) {
        for (ConnectionWatch.Transition t : changes) {
            announce(t.to(), t.why());
            switch (t.to()) {
                case ONLINE -> {
                    List<QueuedCall> waiting = new ArrayList<>(awaitingOnline);
                    awaitingOnline.clear();
                    for (QueuedCall s : waiting) {
                        send(s, 1);
                    }
                }
                case LOST -> {
                    failAll(new CallOutcome.Lost(t.why()));
                    // Close and reopen: whatever the old socket still held can never reach the robot.
                    wire.reopen();
                }
                case REFUSED -> failAll(new CallOutcome.Lost(t.why()));
                default -> { }
            }
        }
    }

    private void failAll(CallOutcome.Lost outcome) {
        long n = pending.failAll(outcome) + pacing.failAll(outcome) + awaitingOnline.size();
        for (QueuedCall s : awaitingOnline) {
            s.end(outcome);
        }
        awaitingOnline.clear();
        counters.lost(n);
    }

    private void lose(QueuedCall s, String why) {
        counters.lost(1);
        s.end(new CallOutcome.Lost(why));
    }

    private void runTimers(long now) {
        apply(watch.onTime(now));
        for (PendingCalls.Sent p : pending.expired(now)) {
            QueuedCall s = p.call();
            if (s.idempotent() && p.attempt() <= config.retries() && watch.state() == ConnectionState.ONLINE) {
                counters.retried();
                send(s, p.attempt() + 1);
            } else {
                pending.timeOut(s, clock.nanoTime());
            }
        }
        for (Iterator<QueuedCall> it = awaitingOnline.iterator(); it.hasNext(); ) {
            QueuedCall s = it.next();
            if (now - s.deadlineNanos() >= 0) {
                it.remove();
                lose(s, "no connection within " + s.timeoutMillis() + " ms");
            }
        }
        for (QueuedCall s : pacing.due(now)) {
            ConnectionState state = watch.state();
            if (state == ConnectionState.ONLINE) {
                send(s, 1);
            } else if (state == ConnectionState.CONNECTING) {
                awaitingOnline.add(s);
            } else {
                lose(s, "robot not connected");
            }
        }
    }

    private void announce(ConnectionState next, String why) {
        String text = "nao " + peer + " " + next.name().toLowerCase() + ": " + why;
        LOG.info(text);
        traffic.event(next, text);
        for (Consumer<ConnectionState> l : stateListeners) {
            try {
                l.accept(next);
            } catch (RuntimeException e) {
                LOG.warn("connection state listener failed: {}", e.toString());
            }
        }
    }
}
