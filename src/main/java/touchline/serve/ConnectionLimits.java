package touchline.serve;

/**
 * What connections cost the server before they are viewers. A connection has
 * {@code upgradeMillis} from its accept to finish the WebSocket upgrade (a deadline, not restarted
 * by the bytes it trickles); at most {@code maxUpgrading} connections wait for their upgrade at
 * once (one more closes the one waiting longest, so a real viewer, which upgrades at once, gets
 * in while slow ones are cut); at most {@code maxConnections} are open at all (one more is closed
 * at once). Each cut is counted in the server's refusals.
 *
 * @param maxConnections connections open at once, viewers included
 * @param maxUpgrading   connections at once that have not finished the upgrade
 * @param upgradeMillis  from accept to the finished upgrade
 */
public record ConnectionLimits(int maxConnections, int maxUpgrading, long upgradeMillis) {

    public ConnectionLimits {
        if (maxConnections < 1 || maxUpgrading < 1 || upgradeMillis < 1) {
            throw new IllegalArgumentException("connection limits must be positive");
        }
    }

    /** 96 connections (64 viewers and room to refuse more politely), 16 upgrading, 10 s to upgrade. */
    public static ConnectionLimits defaults() {
        return new ConnectionLimits(96, 16, 10_000);
    }
}
