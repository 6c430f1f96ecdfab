package touchline.serve;

import touchline.game.MatchMode;
import touchline.protocol.MessageKinds;
import touchline.transport.EnvelopeBus;
import touchline.transport.MicrosClock;

/**
 * A console's stream served to viewers: the {@link FoxgloveServer} subscribed to the console's
 * Envelope stream, with its match mode as a channel. What {@code touchline serve} and the
 * window's "Serve to viewers" both start, so the two serve exactly the same way.
 */
public final class Serving implements AutoCloseable {

    private final FoxgloveServer server;
    private final AutoCloseable subscription;

    /**
     * Binds and starts serving; IllegalArgumentException (a sentence for the user) for a
     * configuration that cannot be served (no token beyond loopback, a certificate that does
     * not load), the bind's own exception when the port cannot be had. {@code teamBudget}: the
     * console's budget guard while it has one (served as {@code /team/budget}).
     */
    public Serving(ServeConfig config, MessageKinds kinds, MicrosClock clock, EnvelopeBus bus, MatchMode matchMode,
                   java.util.function.Supplier<java.util.Optional<touchline.model.TeamMessageBudget>> teamBudget)
            throws InterruptedException {
        server = new FoxgloveServer(config, kinds, clock);
        server.serveMatchMode(matchMode);
        server.serveTeamBudget(teamBudget);
        subscription = bus.subscribe(server);
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
    }
}
