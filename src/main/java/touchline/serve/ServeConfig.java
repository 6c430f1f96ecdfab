package touchline.serve;

import java.net.InetAddress;
import java.net.UnknownHostException;

/**
 * Where and how the live server listens. Loopback by default; an address other viewers can
 * reach needs a {@code token} (the server refuses to start without one).
 *
 * @param bindAddress      local address to listen on
 * @param port             TCP port (0 picks a free one)
 * @param token            what a viewer must present as {@code ?token=…}, or null for none
 * @param maxFrameBytes    the largest frame a viewer may send (its ops are small JSON texts)
 * @param queueLimit       messages pending per viewer before the oldest give way
 * @param timeEveryMillis  how often each viewer is sent the server time
 * @param maxViewers       viewers at once; one more is told so and disconnected
 * @param tlsCert          PEM certificate (chain) to serve {@code wss://} with, or null for plain {@code ws://}
 * @param tlsKey           the certificate's PEM private key (PKCS#8), or null
 * @param limits           connections at once, and how many and how long before the upgrade
 * @param origins          the web pages that may watch (a tool sends no origin and always may)
 */
public record ServeConfig(String bindAddress, int port, String token, int maxFrameBytes, int queueLimit,
                          long timeEveryMillis, int maxViewers, java.nio.file.Path tlsCert, java.nio.file.Path tlsKey,
                          ConnectionLimits limits, AllowedOrigins origins) {

    public static final int DEFAULT_PORT = 8765;

    public static ServeConfig defaults() {
        return new ServeConfig("127.0.0.1", DEFAULT_PORT, null, 64 * 1024, 1024, 100, 64, null, null,
                ConnectionLimits.defaults(), AllowedOrigins.known());
    }

    public ServeConfig withBind(String address) {
        return new ServeConfig(address, port, token, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, limits, origins);
    }

    public ServeConfig withPort(int p) {
        return new ServeConfig(bindAddress, p, token, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, limits, origins);
    }

    public ServeConfig withToken(String t) {
        return new ServeConfig(bindAddress, port, t, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, limits, origins);
    }

    public ServeConfig withQueueLimit(int limit) {
        return new ServeConfig(bindAddress, port, token, maxFrameBytes, limit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, limits, origins);
    }

    public ServeConfig withMaxViewers(int max) {
        return new ServeConfig(bindAddress, port, token, maxFrameBytes, queueLimit, timeEveryMillis, max, tlsCert,
                tlsKey, limits, origins);
    }

    /** Serves {@code wss://} with this PEM certificate and key. */
    public ServeConfig withTls(java.nio.file.Path cert, java.nio.file.Path key) {
        return new ServeConfig(bindAddress, port, token, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, cert,
                key, limits, origins);
    }

    public ServeConfig withLimits(ConnectionLimits l) {
        return new ServeConfig(bindAddress, port, token, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, l, origins);
    }

    public ServeConfig withOrigins(AllowedOrigins o) {
        return new ServeConfig(bindAddress, port, token, maxFrameBytes, queueLimit, timeEveryMillis, maxViewers, tlsCert,
                tlsKey, limits, o);
    }

    public boolean tls() {
        return tlsCert != null;
    }

    /** True when the bind address is a loopback address (only this machine can connect). */
    public boolean loopbackOnly() {
        try {
            return InetAddress.getByName(bindAddress).isLoopbackAddress();
        } catch (UnknownHostException e) {
            return false;
        }
    }
}
