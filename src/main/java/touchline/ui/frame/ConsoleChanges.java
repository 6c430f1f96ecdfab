package touchline.ui.frame;

import touchline.app.LiveField;
import touchline.app.game.MatchMode;
import touchline.serve.FoxgloveServer;

import java.util.Optional;
import java.util.function.Supplier;

/**
 * One number that moves whenever anything a view or the status bar shows may have changed:
 * the sum of the console's change counters (every envelope in the network stores, live and
 * replayed, the robot registry, the option lists, the datagrams in and out, the GameController's
 * packets, match mode's turns: play ends by the clock) and, while the window serves, its viewers and what they subscribed to. Each read is a handful of counter reads, so the frame pulse asks it every frame and
 * the idle watch a few times a second from its own thread (the counters are thread-safe).
 */
public final class ConsoleChanges {

    private final LiveField field;
    private final ConsoleStatus status;
    private final Supplier<Optional<FoxgloveServer>> serving;
    private final MatchMode matchMode;

    public ConsoleChanges(LiveField field, MatchMode matchMode, ConsoleStatus status, Supplier<Optional<FoxgloveServer>> serving) {
        this.field = field;
        this.matchMode = matchMode;
        this.status = status;
        this.serving = serving;
    }

    /** Moves with every change (almost always up); equal readings mean nothing changed in between. */
    public synchronized long read() {
        touchline.app.TransportCounts c = field.transportCounts();
        var stores = field.stores();
        return stores.live().network().version() + stores.replay().network().version() + stores.live().latest().version()
                + stores.replay().latest().version() + field.robots().version() + field.options().version()
                + c.datagramsIn() + c.malformedIn() + status.packetsOut() + viewers()
                + matchMode.changes(); // play starts or ends by the clock, nothing else heard
    }

    /** Viewers come, go and subscribe without any datagram: the Viewers view shows them. */
    private long viewers() {
        long n = 0;
        var server = serving.get();
        if (server.isPresent()) {
            n++;
            for (touchline.serve.ViewerInfo v : server.get().viewers()) {
                n += 1 + v.topics().size() + v.dropped();
            }
        }
        return n;
    }
}
