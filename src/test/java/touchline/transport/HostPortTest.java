package touchline.transport;

import org.junit.jupiter.api.Test;

import java.net.InetAddress;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one parser of HOST[:PORT] text typed by users: every form, and what it says about bad text. */
class HostPortTest {

    @Test
    void ipv4WithAndWithoutPort() {
        assertEquals(new HostPort("10.0.0.7", 3838), HostPort.parse("10.0.0.7:3838", 5555));
        assertEquals(new HostPort("10.0.0.7", 5555), HostPort.parse("10.0.0.7", 5555));
        assertEquals(new HostPort("10.0.0.7", 3838), HostPort.parse("  10.0.0.7:3838 ", 5555), "surrounding blanks");
    }

    @Test
    void ipv6InBracketsWithAndWithoutPortAndBare() {
        assertEquals(new HostPort("fe80::1", 3838), HostPort.parse("[fe80::1]:3838", 5555));
        assertEquals(new HostPort("::1", 5555), HostPort.parse("[::1]", 5555));
        assertEquals(new HostPort("::1", 5555), HostPort.parse("::1", 5555), "a bare IPv6 literal has no port");
        assertEquals(new HostPort("2001:db8::7", 5555), HostPort.parse("2001:db8::7", 5555));
    }

    @Test
    void namesAreKeptAsTypedAndNeverLookedUpByParsing() {
        HostPort nao = HostPort.parse("nao.invalid:9559", 5555);
        assertEquals(new HostPort("nao.invalid", 9559), nao);
        assertTrue(nao.unresolved().isUnresolved());
        assertEquals("nao.invalid", nao.unresolved().getHostString());
        assertEquals(new HostPort("localhost", 5555), HostPort.parse("localhost", 5555));
    }

    @Test
    void resolvedLooksTheAddressUp() throws Exception {
        assertEquals(InetAddress.getByName("127.0.0.1"), HostPort.parse("127.0.0.1:11011", 1).resolved().getAddress());
        assertEquals(11011, HostPort.parse("127.0.0.1:11011", 1).resolved().getPort());
    }

    @Test
    void badPortsSayWhichTextAndWhatAPortIs() {
        for (String bad : new String[]{"10.0.0.7:", "10.0.0.7:x", "10.0.0.7:0", "10.0.0.7:65536", "10.0.0.7:-1",
                "10.0.0.7:99999999999", "[::1]:", "[::1]:abc"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> HostPort.parse(bad, 5555), bad);
            assertEquals("bad port in '" + bad + "': give a number from 1 to 65535", e.getMessage());
        }
    }

    @Test
    void missingHostOrBracketIsSaid() {
        assertEquals("no host given (HOST or HOST:PORT)",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse("  ", 5555)).getMessage());
        assertEquals("no host given (HOST or HOST:PORT)",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse(null, 5555)).getMessage());
        assertEquals("':3838': no host before the port",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse(":3838", 5555)).getMessage());
        assertEquals("'[::1:3838': an IPv6 address in brackets needs its ']'",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse("[::1:3838", 5555)).getMessage());
        assertEquals("'[::1]x': after ']' only ':PORT' may follow",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse("[::1]x", 5555)).getMessage());
        assertEquals("'[]:3838': no host before the port",
                assertThrows(IllegalArgumentException.class, () -> HostPort.parse("[]:3838", 5555)).getMessage());
    }

    @Test
    void writtenBackAsTyped() {
        assertEquals("10.0.0.7:3838", HostPort.parse("10.0.0.7:3838", 1).toString());
        assertEquals("[fe80::1]:3838", HostPort.parse("[fe80::1]:3838", 1).toString());
        assertEquals("[::1]:5555", HostPort.parse("::1", 5555).toString());
    }
}
