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
    private final EnvelopeSource stream;
    private AutoCloseable subscription; // these two are set by start()
    private HeapHeadroom headroom;

    /**
     * Serving not yet started ({@link #start()} binds); IllegalArgumentException (a sentence for
     * the user) for a configuration that cannot be served (no token beyond loopback, a
     * certificate that does not load). {@code states}: the
     * console's state served as JSON channels (match mode, the budget meter; the core's
     * {@code app.LiveServing} hands them in, as the server does not know the core).
     */
    public Serving(ServeConfig config, MessageKinds kinds, MicrosClock clock, EnvelopeSource stream,
                   java.util.List<JsonChannel> states) {
        server = new FoxgloveServer(config, kinds, clock);
        this.stream = stream;
        for (JsonChannel s : states) {
            server.serveJson(s);
        }
    }

    /** Binds and starts serving; the bind's own exception when the port cannot be had. */
    public synchronized Serving start() throws InterruptedException {
        server.start();
        subscription = stream.subscribe(server);
        headroom = new HeapHeadroom(HeapHeadroom.WHILE_SERVING); // more heap while serving: issue 16
        return this;
    }

    public FoxgloveServer server() {
        return server;
    }

    /** Stops serving: unsubscribes first, so nothing is queued for viewers being closed. */
    @Override
    public synchronized void close() {
        if (subscription == null) { // never started (or its bind failed)
            server.close();
            return;
        }
        try {
            subscription.close();
        } catch (Exception e) {
            throw new IllegalStateException(e); // unsubscribing cannot fail
        }
        server.close();
        headroom.close();
    }
}
