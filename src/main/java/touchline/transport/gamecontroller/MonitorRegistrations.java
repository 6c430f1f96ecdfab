package touchline.transport.gamecontroller;

import java.net.InetAddress;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The GameControllers this console asked to be a monitor of ("RGTr" sent to their port 3636).
 * Only they may send it their true state ("RGTD"): true data from anyone else is unsolicited,
 * counted and not believed. Thread-safe.
 */
public final class MonitorRegistrations {

    private final Set<InetAddress> gameControllers = ConcurrentHashMap.newKeySet();

    /** Notes that a monitor request went to this GameController host. */
    public void requested(InetAddress gameController) {
        gameControllers.add(gameController);
    }

    public boolean isRegisteredWith(InetAddress gameController) {
        return gameControllers.contains(gameController);
    }
}
