package touchline.serve;

import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * The web origins whose pages may open the live server: the hosted viewers (Foxglove's web
 * app, Lichtblick's web build), {@code file://} (a desktop app's own page; no web site can claim
 * it), and what the user adds ({@code --allow-origin}). Compared without case and without a
 * trailing slash. {@code null} (a sandboxed frame of any page) is never allowed by default.
 */
public final class AllowedOrigins {

    /** The origins allowed without being asked for. */
    public static final List<String> KNOWN = List.of("https://app.foxglove.dev", "https://studio.foxglove.dev",
            "https://lichtblick-suite.github.io", "file://");

    private final Set<String> origins = new LinkedHashSet<>();

    /** The {@link #KNOWN} origins and {@code extra} ones. */
    public AllowedOrigins(List<String> extra) {
        KNOWN.forEach(o -> origins.add(normal(o)));
        extra.forEach(o -> origins.add(normal(o)));
    }

    public static AllowedOrigins known() {
        return new AllowedOrigins(List.of());
    }

    boolean admits(String origin) {
        return origins.contains(normal(origin));
    }

    /** Every allowed origin, the known ones first. */
    public List<String> all() {
        return List.copyOf(origins);
    }

    private static String normal(String origin) {
        String o = origin.strip().toLowerCase(Locale.ROOT);
        return o.endsWith("/") && !o.endsWith("://") ? o.substring(0, o.length() - 1) : o;
    }

    /** An origin as a viewer sent it, short enough for a reply or a log. */
    static String clip(String origin) {
        return origin.length() <= 100 ? origin : origin.substring(0, 100) + "…";
    }
}
