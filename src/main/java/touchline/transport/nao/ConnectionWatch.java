package touchline.transport.nao;

import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The connection state of a NAO link, decided from what the socket monitor reports
 * ({@link NaoConnection.Event}) and from time. The ZMTP greeting, not the TCP connect, makes a
 * link {@link ConnectionState#ONLINE}; a disconnect (peer closed, heartbeat timed out) makes it
 * {@link ConnectionState#LOST}. A failed handshake makes it {@link ConnectionState#REFUSED}
 * with the reason in words; so does, with CURVE on, a connection dropped twice right after the
 * greeting without any reply (a wrong server key: the robot side just closes). A refused link
 * whose new connection stays up for {@link #CURVE_PROBATION_MS} after the greeting is online
 * again. Pure: time is passed in (nanoseconds on any monotonic clock); the link's thread
 * drives it, other threads may read the state and the reason.
 */
final class ConnectionWatch {

    /** A change the link must act on: publish it, and end or send calls as the new state says. */
    record Transition(ConnectionState to, String why) {
    }

    /**
     * How long a CURVE connection must stay up after the greeting before a refused link counts
     * as online again: a failed CURVE handshake ends within a round trip, well under this.
     */
    static final long CURVE_PROBATION_MS = 1000;
    static final String KEY_REFUSED = "the NAO refused our key: give it console.public — see docs/security.md";
    static final String NO_CURVE_HANDSHAKE = "no CURVE handshake with the NAO: it has another key pair than "
            + "our nao-server.public, or runs without keys (then connect with --insecure) — see docs/security.md";
    static final String NO_HANDSHAKE_INSECURE = "no handshake with the NAO: it runs with CURVE keys; give this "
            + "console its keys (--keys) — see docs/security.md";
    static final String DISCONNECTED = "disconnected (peer closed or heartbeat timed out)";

    private final boolean secure;
    private final String peer;
    private volatile ConnectionState state = ConnectionState.CONNECTING;
    private volatile String securityProblem = "";
    // Connections dropped right after the greeting without a reply, with CURVE on.
    private int disconnectsBeforeHandshake;
    private long handshakeAtNanos;
    private boolean repliedSinceHandshake;
    // When a REFUSED link that connected again counts as online (0: none).
    private long probationUntilNanos;

    /** @param peer "host:port", for the texts */
    ConnectionWatch(boolean secure, String peer) {
        this.secure = secure;
        this.peer = peer;
    }

    ConnectionState state() {
        return state;
    }

    /** Why the handshake fails, in words; "" when it does not. */
    String securityProblem() {
        return securityProblem;
    }

    /** What a monitor event changes. After a transition to LOST the link reopens its sockets: read no further events. */
    List<Transition> onEvent(NaoConnection.Event event, long now) {
        switch (event) {
            case KEY_REFUSED:
                return refused(KEY_REFUSED);
            case NO_HANDSHAKE:
                return refused(secure ? NO_CURVE_HANDSHAKE : NO_HANDSHAKE_INSECURE);
            case GREETING:
                // JeroMQ reports the ZMTP greeting, not the end of the CURVE handshake after it.
                handshakeAtNanos = now;
                if (state == ConnectionState.REFUSED) {
                    probationUntilNanos = now + TimeUnit.MILLISECONDS.toNanos(CURVE_PROBATION_MS);
                    return List.of();
                }
                return state == ConnectionState.ONLINE ? List.of() : online("handshake with " + peer);
            case DISCONNECTED:
                probationUntilNanos = 0;
                if (state != ConnectionState.ONLINE) {
                    return List.of();
                }
                boolean curveFailed = secure && !repliedSinceHandshake
                        && now - handshakeAtNanos < TimeUnit.MILLISECONDS.toNanos(CURVE_PROBATION_MS)
                        && ++disconnectsBeforeHandshake >= 2;
                Transition lost = to(ConnectionState.LOST, DISCONNECTED);
                if (!curveFailed) {
                    return List.of(lost);
                }
                securityProblem = NO_CURVE_HANDSHAKE;
                return List.of(lost, to(ConnectionState.REFUSED, NO_CURVE_HANDSHAKE));
            default:
                return List.of();
        }
    }

    /** A refused link whose new connection stayed up through its probation is online again. */
    List<Transition> onTime(long now) {
        if (state == ConnectionState.REFUSED && probationUntilNanos != 0 && now - probationUntilNanos >= 0) {
            probationUntilNanos = 0;
            disconnectsBeforeHandshake = 0;
            securityProblem = "";
            return online("handshake with " + peer);
        }
        return List.of();
    }

    /** A reply arrived: the handshake works. */
    void replied() {
        repliedSinceHandshake = true;
        disconnectsBeforeHandshake = 0;
    }

    /** The link ended. */
    List<Transition> closed(String why) {
        return state == ConnectionState.CLOSED ? List.of() : List.of(to(ConnectionState.CLOSED, why));
    }

    private List<Transition> refused(String why) {
        securityProblem = why;
        if (state == ConnectionState.REFUSED) {
            return List.of();
        }
        probationUntilNanos = 0;
        return List.of(to(ConnectionState.REFUSED, why));
    }

    private List<Transition> online(String why) {
        repliedSinceHandshake = false;
        return List.of(to(ConnectionState.ONLINE, why));
    }

    private Transition to(ConnectionState next, String why) {
        state = next;
        return new Transition(next, why);
    }
}
