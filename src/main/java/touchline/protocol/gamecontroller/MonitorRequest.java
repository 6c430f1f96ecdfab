package touchline.protocol.gamecontroller;

/**
 * The request a monitor application (TeamCommunicationMonitor, a console) sends to UDP 3636 of
 * an HSL GameController to be registered: "RGTr" + u8 version 0, 5 bytes. A registered host
 * then gets the true game state ("RGTD", {@link HslGameState20#trueData()}) on 3838 and the
 * robots' return packets forwarded on 3940 ({@link ForwardedReturnPacket}). The official
 * GameController refuses hosts that sent return packets themselves.
 */
public final class MonitorRequest {

    public static final int SIZE = 5;
    public static final int VERSION = 0;
    public static final int PORT = 3636;

    public byte[] encode() {
        var b = WireChecks.writer(SIZE);
        b.put(WireChecks.MONITOR_REQUEST_MAGIC).put((byte) VERSION);
        return WireChecks.finish(b, SIZE);
    }

    /** Checks a request: exact length, header, version. */
    public Decoded<MonitorRequest> decode(byte[] datagram) {
        Decoded<MonitorRequest> bad = WireChecks.checkFrame(datagram, SIZE, WireChecks.MONITOR_REQUEST_MAGIC);
        if (bad != null) {
            return bad;
        }
        if (datagram[4] != VERSION) {
            return WireChecks.wrongVersion(VERSION, datagram[4] & 0xFF);
        }
        return Decoded.ok(this);
    }
}
