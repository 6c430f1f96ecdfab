package touchline.serve;

import touchline.protocol.MessageKinds;
import touchline.transport.EnvelopeSource;
import touchline.transport.MicrosClock;

/**
 * A console's stream served to viewers: the {@link FoxgloveServer} subscribed to the stream the
 * face names, the console's live stream ({@code console.bus()}: the window's "Serve to viewers",
 * {@code touchline serve}) or, when a recording is served instead of the field ({@code serve
 * --replay}), its replay stream; never both, so a replay open beside the field is not served
 * as live. Match mode is served as a channel. What {@code touchline serve} and the
 * window's "Serve to viewers" both start, so the two serve exactly the same way.
 */
public final class Serving implements AutoCloseable {

    private final FoxgloveServer server;
    private final AutoCloseable subscription;
    private final HeapHeadroom headroom;

    /**
     * Binds and starts serving; IllegalArgumentException (a sentence for the user) for a
     * configuration that cannot be served (no token beyond loopback, a certificate that does
     * not load), the bind's own exception when the port cannot be had. {@code states}: the
     * console's state served as JSON channels (match mode, the budget meter; the core's
     * {@code app.LiveServing} hands them in, as the server does not know the core).
     */
    public Serving(ServeConfig config, MessageKinds kinds, MicrosClock clock, EnvelopeSource stream,
                   java.util.List<JsonChannel> states)
            throws InterruptedException {
        server = new FoxgloveServer(config, kinds, clock);
        for (JsonChannel s : states) {
            server.serveJson(s);
        }
        subscription = stream.subscribe(server);
        headroom = new HeapHeadroom(HeapHeadroom.WHILE_SERVING); // more heap while serving: issue 16
    }

    public FoxgloveServer server() {
        return server;
    }

    /** Stops serving: unsubscribes first, so nothing is queued for viewers being closed. */
    @Override
    public void close() {
        try {
            subscription.close();
        } catch (Exception e) {
            throw new IllegalStateException(e); // unsubscribing cannot fail
        }
        server.close();
        headroom.close();
    }
}
