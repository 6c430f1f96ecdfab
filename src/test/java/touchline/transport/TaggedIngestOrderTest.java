package touchline.transport;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.security.Authenticity;
import touchline.security.CounterSource;
import touchline.security.LinkSecurity;
import touchline.security.MessageTag;
import touchline.security.TeamKey;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

/**
 * With a team key the event loop decodes each robot datagram and the publishing thread checks
 * its tag and counter, in arrival order with the reliable stream's segments that share the
 * robot's counter (issue 15). The real pipeline on loopback; reading is paused while a robot's
 * datagrams are queued, so they arrive in one drain, handed over in batches.
 */
class TaggedIngestOrderTest {

    private final LinkedBlockingQueue<Envelope> received = new LinkedBlockingQueue<>();
    private final FrameCodec frames = new FrameCodec();
    private final TeamKey key = new TeamKey(new byte[32]);
    private final MessageTag robotSide = new MessageTag(key);
    private UdpTransport transport;
    private ReliableStreamHandler reliable;
    private DatagramSocket robot;

    @BeforeEach
    void start() throws Exception {
        reliable = new ReliableStreamHandler(received::add, new touchline.app.SystemClock());
        transport = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                LinkSecurity.with(key, new CounterSource(() -> 1_000_000L, CounterSource.inMemory())),
                new MessageCodec(new MessageKinds()), received::add, new touchline.app.SystemClock(), reliable);
        reliable.useAuth(transport.segmentAuth());
        transport.start();
        robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        robot.setSoTimeout(5000);
    }

    @AfterEach
    void stop() {
        transport.close();
        robot.close();
    }

    private void send(byte[] bytes) throws Exception {
        robot.send(new DatagramPacket(bytes, bytes.length, InetAddress.getLoopbackAddress(), transport.localPort()));
    }

    private Envelope next() throws InterruptedException {
        Envelope e = received.poll(touchline.testing.Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
        assertNotNull(e, "no envelope within " + touchline.testing.Await.FLOOR_MILLIS + " ms");
        return e;
    }

    /** The next envelope that came in (the console's acks to the segments go out between). */
    private Envelope nextIn() throws InterruptedException {
        Envelope e = next();
        while (e.direction() == Direction.OUT) {
            e = next();
        }
        return e;
    }

    private byte[] status(int id) {
        return frames.encode(Framing.LEGACY, Fumanoid.Message.newBuilder().setRobotID(id)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
    }

    private byte[] tagged(int robotId, long counter, byte[] payload) {
        return robotSide.append(MessageTag.FROM_ROBOT, robotId, counter, payload);
    }

    /** A reliable-stream data segment: sequence {@code seq}, acknowledging nothing yet (modulus 21). */
    private static byte[] segment(int seq, String text) {
        byte[] payload = text.getBytes(StandardCharsets.US_ASCII);
        byte[] s = new byte[payload.length + 2];
        s[0] = (byte) seq;
        s[1] = 20;
        System.arraycopy(payload, 0, s, 2, payload.length);
        return s;
    }

    @Test
    void aForgedDatagramIsDecodedButNeverPublishedNorLearnedAndItsCounterIsNotTaken() throws Exception {
        InetSocketAddress source = (InetSocketAddress) robot.getLocalSocketAddress();
        transport.setReading(false);
        // a well-formed status claiming robot 3 under another team's key, then one with a bad tag and a
        // high counter: both decode, neither may be published, teach the robot's address or take its counter
        send(new MessageTag(new TeamKey(new byte[]{
                1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29,
                30, 31, 32})).append(MessageTag.FROM_ROBOT, 3, 50, status(3)));
        byte[] badTag = tagged(3, 100, status(3));
        badTag[badTag.length - 1] ^= 1;
        send(badTag);
        send(tagged(3, 7, status(3))); // the robot's own next datagram: below the forger's counter, still taken
        transport.setReading(true);

        for (String why : new String[]{"another team key", "bad tag"}) {
            Envelope forged = nextIn();
            assertEquals(Authenticity.FORGED, forged.authenticity(), forged.toString());
            assertEquals("forged", forged.kind());
            assertNull(forged.message(), "the forgery's decoded message is not published");
            assertEquals(source, forged.peer(), "shown with its source");
            assertEquals(3, forged.robotId(), "with the robot it claims");
            assertTrue(forged.error().contains(why), forged.error());
        }
        Envelope genuine = nextIn();
        assertEquals(Authenticity.VERIFIED, genuine.authenticity(), genuine.toString());
        assertEquals("status", genuine.kind());
        assertEquals(2, transport.counters().forgedIn());
        assertEquals(source, transport.peers().peer(3).orElseThrow().address(),
                "the address learned from the genuine datagram only");
    }

    @Test
    void aForgedDatagramAloneTeachesNoAddress() throws Exception {
        byte[] badTag = tagged(4, 1, status(4));
        badTag[badTag.length - 1] ^= 1;
        send(badTag);
        assertEquals(Authenticity.FORGED, nextIn().authenticity());
        assertTrue(transport.peers().peer(4).isEmpty(), "no way back to a robot only a forger spoke for");
        assertEquals(1, transport.counters().forgedIn());
    }

    @Test
    void segmentsAndDatagramsWithTheRobotsNextCountersAreAcceptedInArrivalOrderAndAReplayIsRefused() throws Exception {
        InetSocketAddress source = (InetSocketAddress) robot.getLocalSocketAddress();
        ReliableSession session = reliable.open(source);
        transport.setReading(false);
        send(tagged(3, 1, status(3)));                      // teaches robot 3's address: the segments' key
        send(tagged(3, 2, segment(0, "first ")));
        send(tagged(3, 3, status(3)));
        send(tagged(3, 4, segment(1, "second")));
        send(tagged(3, 4, segment(1, "second")));           // the same segment again: counter replayed
        send(tagged(3, 3, status(3)));                      // a datagram replayed behind the segment
        send(tagged(3, 5, status(3)));
        transport.setReading(true);

        String[] expected = {"status", "reliable.data", "status", "reliable.data", "forged", "forged", "status"};
        for (int i = 0; i < expected.length; i++) {
            Envelope e = nextIn();
            assertEquals(expected[i], e.kind(), "datagram " + i + " in its place: " + e);
            if (!"forged".equals(expected[i]) && e.channel() == Channel.FUMANOID) {
                assertEquals(Authenticity.VERIFIED, e.authenticity(), e.toString());
            }
        }
        assertEquals(2, transport.counters().forgedIn(), "the replayed segment and the replayed datagram");
        assertEquals("first ", new String(session.inbox().poll(30, TimeUnit.SECONDS), StandardCharsets.US_ASCII));
        assertEquals("second", new String(session.inbox().poll(30, TimeUnit.SECONDS), StandardCharsets.US_ASCII));
        assertNull(session.inbox().poll(), "the replayed segment was not delivered again");
    }
}
