package touchline.ui;

import touchline.app.Console;
import touchline.transport.TrafficCounters;

/**
 * One number that moves whenever anything a view or the status bar shows may have changed:
 * the sum of the console's change counters (every envelope in the network stores, live and
 * replayed, the robot registry, the option lists, the datagrams in and out, the GameController's
 * packets). Each read is a handful of counter reads, so the frame pulse asks it every frame and
 * the idle watch a few times a second from its own thread (the counters are thread-safe).
 */
public final class ConsoleChanges {

    private final Console console;
    private final ConsoleStatus status;

    public ConsoleChanges(Console console) {
        this.console = console;
        this.status = new ConsoleStatus(console);
    }

    /** Goes up (never down) with every change; equal readings mean nothing changed in between. */
    public synchronized long read() {
        TrafficCounters c = console.udp().counters();
        var stores = console.stores();
        return stores.live().network().version() + stores.replay().network().version() + stores.live().latest().version()
                + stores.replay().latest().version() + console.robots().version() + console.options().version()
                + c.datagramsIn() + c.malformedIn() + status.packetsOut();
    }
}
