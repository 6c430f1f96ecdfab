package touchline.model;

import touchline.transport.Origin;

import java.net.InetSocketAddress;

/**
 * What one sender address has sent, good and bad, with the last reason it was rejected. A
 * recording's sender is counted apart from the live sender at the same address.
 */
public record SourceSnapshot(InetSocketAddress address, long packets, long malformed, String lastError,
                             long lastSeenMicros, Origin origin) {

    /** The address as views show it, {@code " (replay)"} after a recording's sender. */
    public String label() {
        return address + (origin == Origin.REPLAY ? " (replay)" : "");
    }
}
