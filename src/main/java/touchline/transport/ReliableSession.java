package touchline.transport;

import touchline.protocol.reliable.ReliableStream;

import java.net.InetSocketAddress;
import java.util.ArrayDeque;
import java.util.Queue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.function.Consumer;

/**
 * A reliable stream to one peer as callers see it: offer payloads (queued, sent one at a
 * time), read what arrived in order. The stream itself runs on the UDP event loop; with a team
 * key the segments that arrive are fed to it from the publishing thread (after their tag check,
 * in order with the robots' datagrams), so its methods are synchronized.
 */
public final class ReliableSession {

    private final InetSocketAddress peer;
    final ReliableStream stream;
    private final Queue<byte[]> outbox = new ArrayDeque<>();
    private final LinkedBlockingQueue<byte[]> inbox = new LinkedBlockingQueue<>();
    private volatile Consumer<byte[]> listener;
    private volatile boolean idle = true;

    ReliableSession(InetSocketAddress peer, ReliableStream.Output output, long now) {
        this.peer = peer;
        this.stream = new ReliableStream(ReliableStream.DEFAULT_MODULUS, 100, 250, output, this::delivered, now);
    }

    private void delivered(byte[] payload) {
        Consumer<byte[]> l = listener;
        if (l != null) {
            l.accept(payload);
        } else {
            inbox.add(payload);
        }
    }

    public InetSocketAddress peer() {
        return peer;
    }

    /** Queues a payload (at most 1398 bytes) for lossless, in-order delivery. */
    public void offer(byte[] payload) {
        if (payload.length == 0 || payload.length > ReliableStream.MAX_PAYLOAD) {
            throw new IllegalArgumentException("a segment carries 1.." + ReliableStream.MAX_PAYLOAD + " bytes, not " + payload.length);
        }
        synchronized (outbox) {
            outbox.add(payload);
            idle = false;
        }
    }

    /**
     * Delivers payloads to {@code listener} instead of the inbox: first those already waiting in
     * the inbox (on the caller's thread, in order), then every later one (on the network thread).
     * Nothing that arrived between opening the session and this call is lost: a peer may start sending
     * before the caller installs its listener.
     */
    public synchronized void onReceive(Consumer<byte[]> listener) {
        for (byte[] waiting = inbox.poll(); waiting != null; waiting = inbox.poll()) {
            listener.accept(waiting);
        }
        this.listener = listener;
    }

    public LinkedBlockingQueue<byte[]> inbox() {
        return inbox;
    }

    /** True when everything offered has been acknowledged by the peer. */
    public boolean idle() {
        return idle;
    }

    public synchronized ReliableStream.Stats stats() {
        return stream.stats();
    }

    /** Runs on the event loop: hands the next queued payload to the stream when it is free. */
    synchronized void pump(long now) {
        stream.poll(now);
        if (stream.canSend()) {
            byte[] next;
            synchronized (outbox) {
                next = outbox.poll();
                if (next == null) {
                    idle = true;
                    return;
                }
            }
            stream.send(next, now);
        }
    }

    synchronized void input(byte[] segment, long now) {
        stream.input(segment, now);
    }
}
