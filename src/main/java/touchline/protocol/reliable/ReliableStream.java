package touchline.protocol.reliable;

/**
 * One end of the reliable stream, a derivative of the alternating-bit protocol that shares the
 * robot's UDP port: each segment starts with a sequence byte (0..modulus-1, wrapping; modulus
 * at most 42 so the first byte never looks like {@code 00 2A} or {@code R}) and an ack byte
 * (the last sequence number received in order). Two bytes alone are a pure ack. Stop-and-wait:
 * one data segment in flight, sent again every {@code rtoMillis} until acknowledged;
 * duplicates and out-of-order segments are acknowledged and dropped; when idle a pure ack goes
 * out every {@code keepAliveMillis}. Message boundaries are kept: one send is one delivery.
 *
 * <p>Pure state machine: time comes in as arguments, segments go out through {@link Output};
 * the C firmware ({@code fw_reliable.c}) implements the same rules and interoperates.
 */
public final class ReliableStream {

    public static final int DEFAULT_MODULUS = 21;
    public static final int MAX_MODULUS = 42;
    public static final int MAX_PAYLOAD = 1400 - 2;

    /** Where segments go (header and payload in one datagram). */
    @FunctionalInterface
    public interface Output {
        void segment(byte[] datagram);
    }

    /** Where in-order payloads go. */
    @FunctionalInterface
    public interface Delivery {
        void deliver(byte[] payload);
    }

    /** Counters for the user and the benchmarks. */
    public record Stats(long dataSent, long retransmissions, long acksSent, long delivered, long duplicates, long invalid) { }

    private final int modulus;
    private final long rtoMillis;
    private final long keepAliveMillis;
    private final Output output;
    private final Delivery delivery;
    private int txSeq;
    private int rxLast;
    private boolean inFlight;
    private boolean ackDue;
    private byte[] txPayload;
    private long txSentAt;
    private long lastOutAt;
    private long dataSent;
    private long retransmissions;
    private long acksSent;
    private long delivered;
    private long duplicates;
    private long invalid;

    public ReliableStream(int modulus, long rtoMillis, long keepAliveMillis, Output output, Delivery delivery, long now) {
        if (modulus < 2 || modulus > MAX_MODULUS) {
            throw new IllegalArgumentException("modulus must be 2.." + MAX_MODULUS + ", was " + modulus);
        }
        this.modulus = modulus;
        this.rtoMillis = rtoMillis;
        this.keepAliveMillis = keepAliveMillis;
        this.output = output;
        this.delivery = delivery;
        this.rxLast = modulus - 1; // "received the one before 0": expect 0 next
        this.txSentAt = now;
        this.lastOutAt = now;
    }

    public boolean canSend() {
        return !inFlight;
    }

    /** @return false while a segment is in flight (try again later) or for an empty/oversized payload */
    public boolean send(byte[] payload, long now) {
        if (inFlight || payload.length == 0 || payload.length > MAX_PAYLOAD) {
            return false;
        }
        txPayload = payload.clone();
        inFlight = true;
        txSentAt = now;
        dataSent++;
        emit(txPayload, now);
        return true;
    }

    public void input(byte[] segment, long now) {
        if (segment.length < 2 || (segment[0] & 0xFF) >= modulus || (segment[1] & 0xFF) >= modulus) {
            invalid++;
            return;
        }
        int seq = segment[0] & 0xFF;
        int ack = segment[1] & 0xFF;
        if (inFlight && ack == txSeq) {
            inFlight = false;
            txPayload = null;
            txSeq = (txSeq + 1) % modulus;
        }
        if (segment.length == 2) {
            return; // pure ack: its sequence byte carries no meaning
        }
        if (seq == (rxLast + 1) % modulus) {
            rxLast = seq;
            delivered++;
            delivery.deliver(java.util.Arrays.copyOfRange(segment, 2, segment.length));
        } else {
            duplicates++;
        }
        ackDue = true;
    }

    /** Retransmissions, due acks and keep-alive acks; call every few milliseconds. */
    public void poll(long now) {
        if (inFlight && now - txSentAt >= rtoMillis) {
            txSentAt = now;
            retransmissions++;
            emit(txPayload, now);
            return;
        }
        if (ackDue || (!inFlight && now - lastOutAt >= keepAliveMillis)) {
            int prev = (txSeq + modulus - 1) % modulus;
            output.segment(new byte[]{(byte) (inFlight ? txSeq : prev), (byte) rxLast});
            acksSent++;
            ackDue = false;
            lastOutAt = now;
        }
    }

    private void emit(byte[] payload, long now) {
        byte[] d = new byte[2 + payload.length];
        d[0] = (byte) txSeq;
        d[1] = (byte) rxLast;
        System.arraycopy(payload, 0, d, 2, payload.length);
        ackDue = false; // piggy-backed
        lastOutAt = now;
        output.segment(d);
    }

    public Stats stats() {
        return new Stats(dataSent, retransmissions, acksSent, delivered, duplicates, invalid);
    }
}
