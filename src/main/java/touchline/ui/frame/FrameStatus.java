package touchline.ui.frame;

/** What the frame pulse refreshes after the views each working frame, and tells when it goes idle (the window's status bar). */
public interface FrameStatus {

    /** After the views pulled: the frame's time, the frames a second, the latency shown. FX thread. */
    void refresh(long nowMicros, double framesPerSecond, LatencyProbe latency);

    /** The pulse stopped until something changes. FX thread. */
    void idle();
}
