package touchline.transport.gamecontroller;

import java.net.InetSocketAddress;
import java.util.List;

/**
 * Network settings of the embedded GameController. Every address and port is configurable:
 * tests bind OS-chosen ports on 127.0.0.1 and send only there.
 *
 * @param profile      wire format (explicit, never guessed)
 * @param v7Compat     also send the 116-byte v7 packet every cycle (2014 HL behaviour)
 * @param destinations where game-state packets go (broadcast or unicast, port 3838 in a game)
 * @param senderBind   local address to send from (null: any, ephemeral port)
 * @param returnBind   where return packets are received (0.0.0.0:3939, or :3838 for v8/v7)
 * @param rivalBind    where other GameControllers are listened for (0.0.0.0:3838); null to
 *                     not listen, or when {@code returnBind} is already the game-state port
 * @param intervalMs   send period
 * @param realtime     ask for real-time scheduling of the sender thread (Linux, CAP_SYS_NICE)
 */
public record GcConfig(GcProfile profile, boolean v7Compat, List<InetSocketAddress> destinations,
                       InetSocketAddress senderBind, InetSocketAddress returnBind, InetSocketAddress rivalBind,
                       long intervalMs, boolean realtime) {

    public static final String DEFAULT_BROADCAST = "255.255.255.255";
    public static final long INTERVAL_MS = 500;

    public GcConfig {
        destinations = List.copyOf(destinations);
    }

    /** Official defaults for a profile: broadcast to 3838, returns on the profile's port. */
    public static GcConfig defaults(GcProfile profile) {
        InetSocketAddress returns = new InetSocketAddress(profile.defaultReturnPort());
        InetSocketAddress rivals = profile.returnsOnGameStatePort() ? null
                : new InetSocketAddress(GcProfile.GAME_STATE_PORT);
        return new GcConfig(profile, false,
                List.of(new InetSocketAddress(DEFAULT_BROADCAST, GcProfile.GAME_STATE_PORT)), null, returns, rivals,
                INTERVAL_MS, false);
    }
}
