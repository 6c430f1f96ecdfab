package touchline.transport;

import org.junit.jupiter.api.Test;

import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The session as a caller sees it: a peer may send before the caller installs its listener
 * (a robot streams a file as soon as the console answers); what arrived in between is handed to
 * the listener first, in order, and nothing is left behind in the inbox.
 */
class ReliableSessionTest {

    /** A data segment: sequence {@code seq}, acknowledging nothing yet (modulus 21). */
    static byte[] segment(int seq, String text) {
        byte[] payload = text.getBytes(StandardCharsets.US_ASCII);
        byte[] s = new byte[payload.length + 2];
        s[0] = (byte) seq;
        s[1] = 20; // "received the one before 0" with the default modulus 21
        System.arraycopy(payload, 0, s, 2, payload.length);
        return s;
    }

    @Test
    void payloadsThatArrivedBeforeTheListenerReachItInOrder() {
        List<byte[]> out = new ArrayList<>();
        ReliableSession session = new ReliableSession(new InetSocketAddress("127.0.0.1", 9), out::add, 0);
        session.input(segment(0, "first "), 1);
        session.input(segment(1, "second "), 2);

        StringBuilder got = new StringBuilder();
        session.onReceive(p -> got.append(new String(p, StandardCharsets.US_ASCII)));
        session.input(segment(2, "third"), 3);

        assertEquals("first second third", got.toString());
        assertTrue(session.inbox().isEmpty(), "nothing left behind in the inbox");
    }

    @Test
    void withoutAListenerPayloadsWaitInTheInbox() {
        ReliableSession session = new ReliableSession(new InetSocketAddress("127.0.0.1", 9), d -> { }, 0);
        session.input(segment(0, "kept"), 1);
        assertEquals("kept", new String(session.inbox().poll(), StandardCharsets.US_ASCII));
    }
}
