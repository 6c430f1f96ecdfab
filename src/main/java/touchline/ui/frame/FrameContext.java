package touchline.ui.frame;

/**
 * What a view needs in one frame: the time of the pulse and where to report how old the data
 * it just put on screen is (datagram receive time to this pulse).
 */
public final class FrameContext {

    private final LatencyProbe latency;
    private long nowMicros;
    private long frame;

    public FrameContext(LatencyProbe latency) {
        this.latency = latency;
    }

    void begin(long nowMicros) {
        this.nowMicros = nowMicros;
        frame++;
    }

    public long nowMicros() {
        return nowMicros;
    }

    public long frame() {
        return frame;
    }

    /** A view shows data received at {@code receivedMicros} for the first time in this frame. */
    public void shown(long receivedMicros) {
        latency.record(nowMicros - receivedMicros);
    }
}
