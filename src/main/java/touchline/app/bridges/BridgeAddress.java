package touchline.app.bridges;

import java.net.URI;
import java.net.URISyntaxException;
import java.util.Locale;

/**
 * One robot's bridge as a user names it: {@code ws://10.0.0.11:8765/} or
 * {@code booster-1=ws://10.0.0.11:8765/} (on the command line, in a team file). Without a
 * name the robot is called by its host and port.
 */
public record BridgeAddress(String name, URI url) {

    /** {@code URL} or {@code NAME=URL}; IllegalArgumentException, in words, when it is neither. */
    public static BridgeAddress parse(String text) {
        String t = text.trim();
        int eq = t.indexOf('=');
        int scheme = t.indexOf("://");
        String name = eq > 0 && (scheme < 0 || eq < scheme) ? t.substring(0, eq).trim() : "";
        String url = name.isEmpty() ? t : t.substring(eq + 1).trim();
        return of(name, url);
    }

    /** A named bridge ({@code name} "" for one named by its address). */
    public static BridgeAddress of(String name, String url) {
        URI u;
        try {
            u = new URI(url);
        } catch (URISyntaxException e) {
            throw new IllegalArgumentException("not a URL: " + url + " (" + e.getReason() + ")");
        }
        String s = u.getScheme() == null ? "" : u.getScheme().toLowerCase(Locale.ROOT);
        if (!s.equals("ws") && !s.equals("wss") || u.getHost() == null) {
            throw new IllegalArgumentException("not a WebSocket URL (ws://HOST:8765/ or NAME=ws://…): " + url);
        }
        return new BridgeAddress(name.isEmpty() ? u.getHost() + ":" + (u.getPort() < 0 ? 8765 : u.getPort()) : name, u);
    }
}
