package touchline.transport;

import java.net.InetSocketAddress;

/**
 * A host and port as a user types them: {@code HOST}, {@code HOST:PORT}, {@code [IPv6]},
 * {@code [IPv6]:PORT}, or a bare IPv6 literal such as {@code ::1} (which has no room for a port).
 * The one parser of such text for every face (a GameController's destinations, a NAO's address);
 * recordings' and servers' peer text has its own, lookup-free reader ({@link PeerText}). Parsing
 * never looks a name up; {@link #resolved()} does.
 *
 * @param host a name or an address literal, without brackets
 * @param port 1 to 65535
 */
public record HostPort(String host, int port) {

    public HostPort {
        if (host == null || host.isBlank()) {
            throw new IllegalArgumentException("no host given");
        }
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("port " + port + " is not between 1 and 65535");
        }
    }

    /**
     * Reads {@code text}; {@code defaultPort} when it names no port.
     *
     * @throws IllegalArgumentException with a sentence that quotes the text and says what is wrong
     */
    public static HostPort parse(String text, int defaultPort) {
        String t = text == null ? "" : text.strip();
        if (t.isEmpty()) {
            throw new IllegalArgumentException("no host given (HOST or HOST:PORT)");
        }
        String host;
        String port;
        if (t.startsWith("[")) {
            int close = t.indexOf(']');
            if (close < 0) {
                throw new IllegalArgumentException("'" + t + "': an IPv6 address in brackets needs its ']'");
            }
            host = t.substring(1, close);
            String rest = t.substring(close + 1);
            if (!rest.isEmpty() && !rest.startsWith(":")) {
                throw new IllegalArgumentException("'" + t + "': after ']' only ':PORT' may follow");
            }
            port = rest.isEmpty() ? null : rest.substring(1);
        } else {
            int colon = t.indexOf(':');
            boolean onePort = colon >= 0 && t.indexOf(':', colon + 1) < 0;
            host = onePort ? t.substring(0, colon) : t; // two colons or more: a bare IPv6 address
            port = onePort ? t.substring(colon + 1) : null;
        }
        if (host.isBlank()) {
            throw new IllegalArgumentException("'" + t + "': no host before the port");
        }
        return new HostPort(host, port == null ? defaultPort : port(t, port));
    }

    private static int port(String text, String port) {
        if (!port.isEmpty() && port.length() <= 5 && port.chars().allMatch(c -> c >= '0' && c <= '9')) {
            int p = Integer.parseInt(port);
            if (p >= 1 && p <= 65535) {
                return p;
            }
        }
        throw new IllegalArgumentException("bad port in '" + text + "': give a number from 1 to 65535");
    }

    /** The address, the host name looked up now (unresolved when the lookup fails). */
    public InetSocketAddress resolved() {
        return new InetSocketAddress(host, port);
    }

    /** The address without a lookup. */
    public InetSocketAddress unresolved() {
        return InetSocketAddress.createUnresolved(host, port);
    }

    /** As the user would type it again: {@code host:port}, {@code [v6]:port}. */
    @Override
    public String toString() {
        return (host.indexOf(':') >= 0 ? "[" + host + "]" : host) + ":" + port;
    }
}
