package touchline.transport;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The transport choice: epoll with recvmmsg where it loads, NIO (said why) where it does not or when asked. */
class UdpBackendTest {

    @Test
    void autoTakesEpollWithRecvmmsgWhereItLoads() {
        UdpBackend b = UdpBackend.choose("auto", true, "");
        assertEquals(UdpBackend.Kind.EPOLL_MMSG, b.kind());
        assertTrue(b.epoll());
        assertTrue(b.recvmmsg());
        assertEquals("epoll + recvmmsg", b.describe());
    }

    @Test
    void autoFallsBackToNioAndSaysWhyWhereEpollIsMissing() {
        UdpBackend b = UdpBackend.choose("auto", false, "failed to load libnetty_transport_native_epoll");
        assertEquals(UdpBackend.Kind.NIO, b.kind());
        assertFalse(b.epoll());
        assertEquals("NIO (portable fallback, epoll not available here: failed to load libnetty_transport_native_epoll)",
                b.describe());
    }

    @Test
    void askingForEpollOnAMachineWithoutItStillRunsOnNio() {
        assertEquals(UdpBackend.Kind.NIO, UdpBackend.choose("epoll", false, "not Linux").kind());
        assertEquals(UdpBackend.Kind.NIO, UdpBackend.choose("epoll-mmsg", false, "").kind());
        assertEquals("NIO (portable fallback, epoll not available here)", UdpBackend.choose("epoll", false, "").describe());
    }

    @Test
    void nioWhenAskedForEvenWhereEpollLoads() {
        UdpBackend b = UdpBackend.choose("NIO", true, "");
        assertEquals(UdpBackend.Kind.NIO, b.kind());
        assertEquals("NIO (asked for)", b.describe());
        assertEquals(UdpBackend.Kind.EPOLL, UdpBackend.choose("epoll", true, "").kind());
        assertFalse(UdpBackend.choose("epoll", true, "").recvmmsg());
    }

    @Test
    void anUnknownNameIsRefusedWithTheNamesThatWork() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> UdpBackend.choose("kqueue", true, ""));
        assertEquals("unknown UDP transport \"kqueue\": use auto, epoll-mmsg, epoll or nio", e.getMessage());
    }

    @Test
    void aTransportAskedForNioBindsAndSaysSo() throws Exception {
        UdpConfig config = UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0).withTransport("nio");
        try (UdpTransport t = new UdpTransport(config, new touchline.protocol.MessageCodec(new touchline.protocol.MessageKinds()), e -> { },
                new touchline.app.SystemClock()).start()) {
            assertTrue(t.localPort() > 0);
            assertEquals(UdpBackend.Kind.NIO, t.backend().kind());
        }
    }
}
