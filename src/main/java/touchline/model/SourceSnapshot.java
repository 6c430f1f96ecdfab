package touchline.model;

import java.net.InetSocketAddress;

/** What one sender address has sent, good and bad, with the last reason it was rejected. */
public record SourceSnapshot(InetSocketAddress address, long packets, long malformed, String lastError,
                             long lastSeenMicros) { }
