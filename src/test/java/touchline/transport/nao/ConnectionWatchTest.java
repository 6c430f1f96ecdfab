package touchline.transport.nao;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static touchline.transport.nao.NaoConnection.Event.DISCONNECTED;
import static touchline.transport.nao.NaoConnection.Event.GREETING;
import static touchline.transport.nao.NaoConnection.Event.KEY_REFUSED;
import static touchline.transport.nao.NaoConnection.Event.NO_HANDSHAKE;
import static touchline.transport.nao.NaoConnection.Event.OTHER;

/** The link's connection state alone, on a fake clock: monitor events and times are plain values. */
class ConnectionWatchTest {

    private static final long MS = TimeUnit.MILLISECONDS.toNanos(1);

    private static ConnectionWatch.Transition to(ConnectionState s, String why) {
        return new ConnectionWatch.Transition(s, why);
    }

    @Test
    void theGreetingMakesALinkOnlineAndADisconnectLost() {
        ConnectionWatch watch = new ConnectionWatch(false, "nao:5555");
        assertEquals(ConnectionState.CONNECTING, watch.state());
        assertEquals(List.of(), watch.onEvent(OTHER, 0), "a TCP connect is not online");
        assertEquals(List.of(to(ConnectionState.ONLINE, "handshake with nao:5555")), watch.onEvent(GREETING, 0));
        assertEquals(List.of(), watch.onEvent(GREETING, MS), "already online");
        assertEquals(List.of(to(ConnectionState.LOST, ConnectionWatch.DISCONNECTED)), watch.onEvent(DISCONNECTED, 2 * MS));
        assertEquals(List.of(), watch.onEvent(DISCONNECTED, 3 * MS));
        assertEquals(List.of(to(ConnectionState.ONLINE, "handshake with nao:5555")), watch.onEvent(GREETING, 4 * MS));
        assertEquals(List.of(to(ConnectionState.CLOSED, "link closed")), watch.closed("link closed"));
        assertEquals(List.of(), watch.closed("link closed"));
    }

    @Test
    void anInsecureLinkToACurveRobotIsRefusedWithWhatToDo() {
        ConnectionWatch watch = new ConnectionWatch(false, "nao:5555");
        assertEquals(List.of(to(ConnectionState.REFUSED, ConnectionWatch.NO_HANDSHAKE_INSECURE)), watch.onEvent(NO_HANDSHAKE, 0));
        assertEquals(List.of(), watch.onEvent(NO_HANDSHAKE, MS), "said once");
        assertEquals(ConnectionWatch.NO_HANDSHAKE_INSECURE, watch.securityProblem());
    }

    @Test
    void aRefusedKeyStaysRefusedUntilANewConnectionOutlivesItsProbation() {
        ConnectionWatch watch = new ConnectionWatch(true, "nao:5555");
        assertEquals(List.of(to(ConnectionState.REFUSED, ConnectionWatch.KEY_REFUSED)), watch.onEvent(KEY_REFUSED, 0));
        assertEquals(List.of(), watch.onEvent(GREETING, 100 * MS), "a greeting alone proves nothing with CURVE");
        long probationEnds = 100 * MS + TimeUnit.MILLISECONDS.toNanos(ConnectionWatch.CURVE_PROBATION_MS);
        assertEquals(List.of(), watch.onTime(probationEnds - 1));
        assertEquals(ConnectionState.REFUSED, watch.state());
        assertEquals(List.of(to(ConnectionState.ONLINE, "handshake with nao:5555")), watch.onTime(probationEnds));
        assertEquals("", watch.securityProblem());
    }

    @Test
    void aDisconnectDuringProbationKeepsItRefused() {
        ConnectionWatch watch = new ConnectionWatch(true, "nao:5555");
        watch.onEvent(KEY_REFUSED, 0);
        watch.onEvent(GREETING, 10 * MS);
        assertEquals(List.of(), watch.onEvent(DISCONNECTED, 20 * MS));
        assertEquals(List.of(), watch.onTime(10_000 * MS));
        assertEquals(ConnectionState.REFUSED, watch.state());
    }

    @Test
    void withCurveTwoQuickDropsAfterTheGreetingWithoutAReplyAreAWrongServerKey() {
        ConnectionWatch watch = new ConnectionWatch(true, "nao:5555");
        watch.onEvent(GREETING, 0);
        assertEquals(List.of(to(ConnectionState.LOST, ConnectionWatch.DISCONNECTED)), watch.onEvent(DISCONNECTED, 5 * MS),
                "the first drop may be the robot restarting");
        watch.onEvent(GREETING, 200 * MS);
        assertEquals(List.of(to(ConnectionState.LOST, ConnectionWatch.DISCONNECTED),
                        to(ConnectionState.REFUSED, ConnectionWatch.NO_CURVE_HANDSHAKE)),
                watch.onEvent(DISCONNECTED, 205 * MS));
        assertEquals(ConnectionWatch.NO_CURVE_HANDSHAKE, watch.securityProblem());
    }

    @Test
    void aReplyProvesTheKeysSoLaterDropsAreOnlyLost() {
        ConnectionWatch watch = new ConnectionWatch(true, "nao:5555");
        watch.onEvent(GREETING, 0);
        watch.onEvent(DISCONNECTED, 5 * MS);
        watch.onEvent(GREETING, 200 * MS);
        watch.replied();
        assertEquals(List.of(to(ConnectionState.LOST, ConnectionWatch.DISCONNECTED)), watch.onEvent(DISCONNECTED, 205 * MS));
        watch.onEvent(GREETING, 400 * MS);
        assertEquals(List.of(to(ConnectionState.LOST, ConnectionWatch.DISCONNECTED)), watch.onEvent(DISCONNECTED, 405 * MS),
                "without CURVE, or after a reply, a drop is a drop");
    }
}
