package touchline.transport;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.util.regex.Pattern;

/**
 * A peer address as text, the way recordings and the live server's channel metadata write it:
 * {@code 10.0.0.7:10001}, or {@code unresolved:nao.local:5555} for an address never resolved.
 * Reading it never causes a name lookup (a file or a server from outside must not): only
 * address literals are turned into addresses, anything else stays unresolved.
 */
public final class PeerText {

    private static final Pattern IPV4 = Pattern.compile("(25[0-5]|2[0-4]\\d|1?\\d?\\d)(\\.(25[0-5]|2[0-4]\\d|1?\\d?\\d)){3}");
    private static final Pattern IPV6 = Pattern.compile("[0-9A-Fa-f:.]*:[0-9A-Fa-f:.]*");

    private PeerText() {
    }

    public static String format(InetSocketAddress peer) {
        if (peer.isUnresolved()) {
            return "unresolved:" + peer.getHostString() + ":" + peer.getPort();
        }
        return peer.getAddress().getHostAddress() + ":" + peer.getPort();
    }

    /** Dotted-quad IPv4 or IPv6 (no zone): forms {@link InetAddress#getByName} parses without any lookup. */
    public static boolean isAddressLiteral(String host) {
        return IPV4.matcher(host).matches() || IPV6.matcher(host).matches();
    }

    /** The address {@link #format} wrote, null for null; a malformed port throws NumberFormatException. */
    public static InetSocketAddress parse(String s) {
        if (s == null) {
            return null;
        }
        int colon = s.lastIndexOf(':');
        int port = Integer.parseInt(s.substring(colon + 1));
        if (s.startsWith("unresolved:")) {
            return InetSocketAddress.createUnresolved(s.substring("unresolved:".length(), colon), port);
        }
        String host = s.substring(0, colon);
        if (!isAddressLiteral(host)) {
            return InetSocketAddress.createUnresolved(host, port);
        }
        try {
            return new InetSocketAddress(InetAddress.getByName(host), port);
        } catch (UnknownHostException e) {
            return InetSocketAddress.createUnresolved(host, port);
        }
    }
}
