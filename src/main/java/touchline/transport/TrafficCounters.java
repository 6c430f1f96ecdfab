package touchline.transport;

import java.util.concurrent.atomic.LongAdder;

/** Channel-level counts of datagrams and bytes in and out, for the status bar and benchmarks. */
public final class TrafficCounters {

    private final LongAdder datagramsIn = new LongAdder();
    private final LongAdder bytesIn = new LongAdder();
    private final LongAdder datagramsOut = new LongAdder();
    private final LongAdder bytesOut = new LongAdder();
    private final LongAdder malformedIn = new LongAdder();
    private final LongAdder held = new LongAdder();
    private final LongAdder forgedIn = new LongAdder();
    private final LongAdder unverifiedIn = new LongAdder();

    void countIn(int bytes) {
        datagramsIn.increment();
        bytesIn.add(bytes);
    }

    void countOut(int bytes) {
        datagramsOut.increment();
        bytesOut.add(bytes);
    }

    void countMalformed() {
        malformedIn.increment();
    }

    void countForged() {
        forgedIn.increment();
    }

    void countUnverified() {
        unverifiedIn.increment();
    }

    void countHeld() {
        held.increment();
    }

    public long datagramsIn() { return datagramsIn.sum(); }
    public long bytesIn() { return bytesIn.sum(); }
    public long datagramsOut() { return datagramsOut.sum(); }
    public long bytesOut() { return bytesOut.sum(); }
    public long malformedIn() { return malformedIn.sum(); }
    public long held() { return held.sum(); }
    /** Robot datagrams dropped for a wrong, cut or replayed tag (with a team key). */
    public long forgedIn() { return forgedIn.sum(); }
    /** Robot datagrams without a tag, taken as unverified. */
    public long unverifiedIn() { return unverifiedIn.sum(); }
}
