package touchline.transport;

import java.util.Locale;

/**
 * Which Netty transport the console's UDP endpoint runs on, and why. Linux's epoll transport
 * with recvmmsg (up to 32 datagrams per system call) reads with far less overhead than NIO;
 * "epoll" reads one datagram per call; NIO runs everywhere (macOS, Windows) and is the
 * portable fallback chosen at run time when epoll is not available. Asked for with
 * {@code --transport} or {@code -Dtouchline.udp=auto|epoll-mmsg|epoll|nio} (default auto).
 *
 * @param kind   the transport in use
 * @param reason why this one: empty when it is what was asked for (or the automatic best)
 */
public record UdpBackend(Kind kind, String reason) {

    /** The system property that asks for a transport (the CLI's {@code --transport} sets it too). */
    public static final String PROPERTY = "touchline.udp";
    public static final String AUTO = "auto";

    public enum Kind {
        EPOLL_MMSG("epoll-mmsg", "epoll + recvmmsg"),
        EPOLL("epoll", "epoll"),
        NIO("nio", "NIO");

        private final String name;
        private final String title;

        Kind(String name, String title) {
            this.name = name;
            this.title = title;
        }

        public String optionName() {
            return name;
        }

        public String title() {
            return title;
        }
    }

    /**
     * Chooses the transport.
     *
     * @param requested      auto, epoll-mmsg, epoll or nio (case ignored)
     * @param epollAvailable whether Netty's native epoll loaded on this machine
     * @param whyNotEpoll    the reason it did not (shown), ignored when available
     * @throws IllegalArgumentException for another name, with the names that work
     */
    public static UdpBackend choose(String requested, boolean epollAvailable, String whyNotEpoll) {
        String r = requested == null ? AUTO : requested.trim().toLowerCase(Locale.ROOT);
        Kind wanted = switch (r) {
            case AUTO, "" -> Kind.EPOLL_MMSG;
            case "epoll-mmsg", "recvmmsg" -> Kind.EPOLL_MMSG;
            case "epoll" -> Kind.EPOLL;
            case "nio" -> Kind.NIO;
            default -> throw new IllegalArgumentException("unknown UDP transport \"" + requested
                    + "\": use auto, epoll-mmsg, epoll or nio");
        };
        if (wanted == Kind.NIO) {
            return new UdpBackend(Kind.NIO, r.equals("nio") ? "asked for" : "");
        }
        if (!epollAvailable) {
            return new UdpBackend(Kind.NIO, "portable fallback, epoll not available here"
                    + (whyNotEpoll == null || whyNotEpoll.isBlank() ? "" : ": " + whyNotEpoll));
        }
        return new UdpBackend(wanted, "");
    }

    /** What this machine's Netty offers: the choice for {@code requested} here. */
    public static UdpBackend onThisMachine(String requested) {
        boolean available;
        String why = "";
        try {
            available = io.netty.channel.epoll.Epoll.isAvailable();
            if (!available) {
                Throwable cause = io.netty.channel.epoll.Epoll.unavailabilityCause();
                why = cause == null ? "" : firstLine(cause);
            }
        } catch (LinkageError e) { // the epoll classes themselves missing from a trimmed class path
            available = false;
            why = firstLine(e);
        }
        return choose(requested, available, why);
    }

    private static String firstLine(Throwable t) {
        String m = t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
        int nl = m.indexOf('\n');
        String line = nl < 0 ? m : m.substring(0, nl);
        return line.length() > 160 ? line.substring(0, 160) + "…" : line;
    }

    public boolean epoll() {
        return kind != Kind.NIO;
    }

    public boolean recvmmsg() {
        return kind == Kind.EPOLL_MMSG;
    }

    /** One phrase for the window and the start line, e.g. "NIO (portable fallback, epoll not available here)". */
    public String describe() {
        return kind.title() + (reason.isEmpty() ? "" : " (" + reason + ")");
    }
}
