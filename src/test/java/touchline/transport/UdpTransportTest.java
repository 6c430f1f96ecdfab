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
import touchline.security.Trailer;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;

import static org.junit.jupiter.api.Assertions.*;

/** The real Netty pipeline on loopback, fed by a plain UDP socket standing in for a robot. */
class UdpTransportTest {

    private final LinkedBlockingQueue<Envelope> received = new LinkedBlockingQueue<>();
    private final FrameCodec frames = new FrameCodec();
    private UdpTransport transport;
    private DatagramSocket robot;

    @BeforeEach
    void start() throws Exception {
        transport = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                new MessageCodec(new MessageKinds()), received::add, new touchline.app.SystemClock()).start();
        robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        robot.setSoTimeout(5000);
    }

    @AfterEach
    void stop() {
        transport.close();
        robot.close();
    }

    private final TeamKey key = new TeamKey(new byte[32]);
    private final MessageTag robotSide = new MessageTag(key);
    private final AtomicLong clock = new AtomicLong(1_000_000L);

    /** While set, the model holds the publishing thread until it is counted down (a slow model). */
    private volatile java.util.concurrent.CountDownLatch slowModel;

    private void publish(Envelope e) {
        java.util.concurrent.CountDownLatch hold = slowModel;
        if (hold != null) {
            try {
                hold.await();
            } catch (InterruptedException ex) {
                Thread.currentThread().interrupt();
            }
        }
        received.add(e);
    }

    /** The same transport, restarted with a team key whose counter follows a fake clock. */
    private void useTeamKey() throws Exception {
        transport.close();
        transport = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                LinkSecurity.with(key, new CounterSource(clock::get, CounterSource.inMemory())),
                new MessageCodec(new MessageKinds()), this::publish, new touchline.app.SystemClock()).start();
    }

    /**
     * With a team key and a reliable stream in the pipeline, its segments checked under the key: the
     * event loop decodes each robot datagram and the publishing thread checks tags and counters in
     * arrival order, the segments' among them (issue 15).
     */
    private ReliableStreamHandler useTeamKeyAndReliableStream() throws Exception {
        transport.close();
        transport = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                LinkSecurity.with(key, new CounterSource(clock::get, CounterSource.inMemory())),
                new MessageCodec(new MessageKinds()), received::add, new touchline.app.SystemClock());
        transport.start();
        return transport.reliable();
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

    private byte[] tagged(int robotId, long counter, byte[] payload) {
        return robotSide.append(MessageTag.FROM_ROBOT, robotId, counter, payload);
    }

    private byte[] status(int id, Framing framing) {
        return frames.encode(framing, Fumanoid.Message.newBuilder().setRobotID(id)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray());
    }

    @Test
    void datagramsWaitInTheSocketWhileReadingIsPausedAndAllArriveInOrderAfter() throws Exception {
        transport.setReading(false);
        for (int id = 1; id <= 200; id++) {
            send(status(id, Framing.LEGACY));
        }
        // A round trip through the event loop: it handles ready sockets before its tasks, so an
        // unpaused channel would have read the datagrams by now.
        transport.setReading(false);
        assertTrue(received.isEmpty(), received.size() + " read while paused");
        transport.setReading(true);
        for (int id = 1; id <= 200; id++) {
            assertEquals(id, next().robotId());
        }
        assertEquals(200, transport.counters().datagramsIn());
    }

    @Test
    void eachBadDatagramIsReportedAndTheNextGoodOneDecodes() throws Exception {
        byte[][] bad = {
                HexFormat.of().parseHex("002a0000"),                          // truncated legacy header
                HexFormat.of().parseHex("002a000000000000000000ff0801"),        // length disagrees
                new byte[1401],                                               // over 1400 bytes
                new byte[9000],                                               // larger than a receive slot (2048)
                frames.encode(Framing.LENGTH_PREFIX, new byte[]{(byte) 0xff, (byte) 0xff, (byte) 0xff}), // protobuf garbage
        };
        for (byte[] b : bad) {
            send(b);
            Envelope e = next();
            assertTrue(e.isMalformed(), e.toString());
            assertEquals("malformed", e.kind());
            send(status(7, Framing.LEGACY));
            Envelope good = next();
            assertFalse(good.isMalformed(), good.toString());
            assertEquals(7, good.robotId());
            assertEquals("status", good.kind());
        }
        assertEquals(bad.length, transport.counters().malformedIn());
    }

    @Test
    void unknownExtensionArrivesAsItsOwnKind() throws Exception {
        byte[] payload = HexFormat.of().parseHex("0803" + "c23e020801"); // robotID 3, field 1000 { 1: 1 }
        send(frames.encode(Framing.LENGTH_PREFIX, payload));
        Envelope e = next();
        assertEquals("ext#1000", e.kind());
        assertEquals(3, e.robotId());
        assertEquals(1, e.message().getUnknownFields().asMap().size());
    }

    @Test
    void answersARobotInTheFramingItUses() throws Exception {
        send(status(4, Framing.LENGTH_PREFIX));
        next();
        MessageCodec codec = new MessageCodec(new MessageKinds());
        assertTrue(transport.send(4, codec.optionListRequest()).isSent());
        DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
        robot.receive(p);
        byte[] got = java.util.Arrays.copyOf(p.getData(), p.getLength());
        assertEquals(got.length - 4, ((got[2] & 0xff) << 8) | (got[3] & 0xff), "4-byte length header");
        Envelope out = next();
        assertEquals(Direction.OUT, out.direction());
        assertEquals("debugOptionListRequest", out.kind());

        send(status(4, Framing.LEGACY));
        next();
        transport.send(4, codec.optionListRequest());
        robot.receive(p);
        assertEquals(0x2a, p.getData()[1], "now the legacy header");
    }

    @Test
    void gateHoldsCommandsBack() throws Exception {
        send(status(4, Framing.LEGACY));
        next();
        transport.setGate(() -> Optional.of(Hold.always("match mode: PLAYING")));
        SendResult r = transport.send(4, new MessageCodec(new MessageKinds()).optionListRequest());
        assertEquals(SendResult.Outcome.HELD, r.outcome());
        assertEquals("match mode: PLAYING", r.reason());
        assertEquals(1, transport.counters().held());
        assertEquals(0, transport.counters().datagramsOut());
    }

    @Test
    void unseenRobotCannotBeAddressed() {
        SendResult r = transport.send(99, new MessageCodec(new MessageKinds()).optionListRequest());
        assertEquals(SendResult.Outcome.FAILED, r.outcome());
        assertTrue(r.reason().contains("not been seen"));
    }

    @Test
    void withATeamKeyTaggedRobotDataIsVerifiedInBothFramingsAndForgeriesAreDroppedWithTheirSource() throws Exception {
        useTeamKey();
        send(robotSide.append(MessageTag.FROM_ROBOT, 3, 1, status(3, Framing.LENGTH_PREFIX)));
        Envelope ok = next();
        assertEquals(Authenticity.VERIFIED, ok.authenticity());
        assertEquals("status", ok.kind(), "the length header is read without the trailer");
        send(robotSide.append(MessageTag.FROM_ROBOT, 3, 2, status(3, Framing.LEGACY)));
        assertEquals(Authenticity.VERIFIED, next().authenticity());

        send(robotSide.append(MessageTag.FROM_ROBOT, 3, 2, status(3, Framing.LEGACY))); // replayed
        Envelope replay = next();
        assertEquals(Authenticity.FORGED, replay.authenticity());
        assertNull(replay.message(), "a forgery's data is not passed on");
        assertTrue(replay.error().contains("replayed"), replay.error());
        send(robotSide.append(MessageTag.FROM_ROBOT, 4, 3, status(3, Framing.LEGACY))); // tagged for robot 4
        assertTrue(next().error().contains("bad tag"));
        send(status(3, Framing.LEGACY)); // untagged in the name of a robot that tags
        assertTrue(next().error().contains("untagged"));
        send(status(5, Framing.LEGACY)); // a robot without a key
        assertEquals(Authenticity.UNTAGGED, next().authenticity());
        assertEquals(3, transport.counters().forgedIn());
        assertEquals(1, transport.counters().unverifiedIn());
        assertTrue(transport.peers().peer(5).isEmpty(), "an untagged robot is no command destination");
        SendResult refused = transport.send(5, Fumanoid.Message.newBuilder().setRobotID(0).setExtension(
                Fumanoid.debugOptionListRequest, Fumanoid.DebugOptionListRequest.getDefaultInstance()).build());
        assertFalse(refused.isSent());
        assertTrue(refused.reason().contains("untagged"), refused.reason());
    }

    @Test
    void withATeamKeyEverythingSentToARobotIsTaggedForThatRobotWithIncreasingCounters() throws Exception {
        useTeamKey();
        send(robotSide.append(MessageTag.FROM_ROBOT, 3, 1, status(3, Framing.LEGACY)));
        next();
        Fumanoid.Message request = Fumanoid.Message.newBuilder().setRobotID(0)
                .setExtension(Fumanoid.debugOptionListRequest, Fumanoid.DebugOptionListRequest.getDefaultInstance()).build();
        long[] counters = new long[2];
        for (int i = 0; i < 2; i++) {
            assertTrue(transport.send(3, request).isSent());
            Envelope out = next();
            assertEquals(Direction.OUT, out.direction());
            DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
            robot.receive(p);
            byte[] wire = Arrays.copyOf(p.getData(), p.getLength());
            assertArrayEquals(wire, out.raw(), "the envelope shows what went out, tag included");
            Trailer t = Trailer.of(wire);
            assertInstanceOf(Trailer.Present.class, t);
            assertEquals(MessageTag.Check.OK, robotSide.check(MessageTag.toRobot(0), 3, wire, t),
                    "tagged for the boot of the robot's counter (boot 0)");
            assertEquals(MessageTag.Check.BAD_TAG, robotSide.check(MessageTag.toRobot(0), 4, wire, t));
            assertEquals(MessageTag.Check.BAD_TAG, robotSide.check(MessageTag.toRobot(1), 3, wire, t),
                    "not valid in another boot of the robot");
            counters[i] = ((Trailer.Present) t).counter();
        }
        assertTrue(counters[1] > counters[0]);
        assertEquals(1_000_000L, counters[0], "the counter follows the (fake) clock");
    }
    @Test
    void withATeamKeyABurstArrivesInOrderWithForgeriesAndMalformedDatagramsInPlace() throws Exception {
        useTeamKey();
        transport.setReading(false);
        long[] counter = new long[5];
        int n = 300; // several socket reads, so several batches handed to the decode thread
        for (int i = 0; i < n; i++) {
            int id = 1 + i % 4;
            if (i % 25 == 7) {
                send(robotSide.append(MessageTag.FROM_ROBOT, id + 1, ++counter[id], status(id, Framing.LEGACY)));
            } else if (i % 25 == 13) {
                send(frames.encode(Framing.LENGTH_PREFIX, new byte[]{(byte) 0xff, (byte) 0xff, (byte) 0xff}));
            } else {
                send(robotSide.append(MessageTag.FROM_ROBOT, id, ++counter[id], status(id, Framing.LEGACY)));
            }
        }
        transport.setReading(true);
        for (int i = 0; i < n; i++) {
            Envelope e = next();
            if (i % 25 == 13) {
                assertTrue(e.isMalformed(), i + ": " + e);
                continue;
            }
            assertEquals(1 + i % 4, e.robotId(), "datagram " + i + " in its place");
            if (i % 25 == 7) {
                assertEquals(Authenticity.FORGED, e.authenticity(), i + ": " + e);
                assertNull(e.message());
            } else {
                assertEquals(Authenticity.VERIFIED, e.authenticity(), i + ": " + e);
                assertEquals("status", e.kind());
            }
        }
        assertEquals(n / 25, transport.counters().forgedIn());
        assertEquals(n / 25, transport.counters().malformedIn());
    }

    /**
     * The model holds the publishing thread while a burst is read, so batches wait for it and the
     * event loop computes their HMACs itself (the stage settling only the counters): the same
     * verdicts, in the same order, forgeries and replays refused.
     */
    @Test
    void withATeamKeyABurstReadWhileTheModelIsSlowKeepsEveryVerdictAndItsOrder() throws Exception {
        useTeamKey();
        java.util.concurrent.CountDownLatch hold = new java.util.concurrent.CountDownLatch(1);
        slowModel = hold;
        int n = 400; // a dozen socket reads or more: most handed over while the stage is held
        long counter = 0;
        for (int i = 0; i < n; i++) {
            if (i % 20 == 5) {
                send(tagged(2, counter, status(2, Framing.LEGACY))); // the last counter again: a replay
            } else if (i % 20 == 11) {
                byte[] bad = tagged(2, ++counter, status(2, Framing.LEGACY));
                bad[bad.length - 1] ^= 1;
                send(bad);
            } else {
                send(tagged(2, ++counter, status(2, Framing.LEGACY)));
            }
        }
        touchline.testing.Await.until("every datagram read", () -> transport.counters().datagramsIn() == n);
        slowModel = null;
        hold.countDown();
        for (int i = 0; i < n; i++) {
            Envelope e = next();
            boolean refused = i % 20 == 5 || i % 20 == 11;
            assertEquals(refused ? Authenticity.FORGED : Authenticity.VERIFIED, e.authenticity(), i + ": " + e);
            if (refused) {
                assertNull(e.message(), i + ": a forgery's message is not published");
                assertTrue(e.error().contains(i % 20 == 5 ? "replayed" : "bad tag"), i + ": " + e.error());
            }
        }
        assertEquals(2L * n / 20, transport.counters().forgedIn());
    }

    @Test
    void withATeamKeyAMessageWithoutRobotIdIsMalformedWithTheDecodersReason() throws Exception {
        useTeamKey();
        send(frames.encode(Framing.LEGACY, HexFormat.of().parseHex("1001")));
        Envelope e = next();
        assertTrue(e.isMalformed(), e.toString());
        assertTrue(e.error().contains("robotID"), e.error());
        assertEquals(0, transport.counters().forgedIn());
    }
    @Test
    void withATeamKeyAPortInUseFailsTheStartAndLeavesNoDecodeThreadBehind() throws Exception {
        // every started transport has its stage thread (this class's own transport too): count the new ones
        long before = decodeThreads();
        try (DatagramSocket taken = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            UdpTransport second = new UdpTransport(
                    UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(taken.getLocalPort()),
                    LinkSecurity.with(key, new CounterSource(clock::get, CounterSource.inMemory())),
                    new MessageCodec(new MessageKinds()), received::add, new touchline.app.SystemClock());
            assertThrows(java.io.IOException.class, second::start); // BindException with NIO, NativeIoException with epoll
            second.close();
        }
        assertEquals(before, decodeThreads(), "a decode thread is left running");
    }

    private static long decodeThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().equals("touchline-decode")).count();
    }

    @Test
    void anOutboundEnvelopeReachesTheSubscribersOnTheTransportsThreadNotTheCallers() throws Exception {
        // today's cause: a click in the options view ran every subscriber (the recorder's encoding
        // included) on the JavaFX thread; the caller here stands in for it
        LinkedBlockingQueue<String> threads = new LinkedBlockingQueue<>();
        transport.close();
        transport = new UdpTransport(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0),
                new MessageCodec(new MessageKinds()), e -> {
                    threads.add(e.direction() + " " + Thread.currentThread().getName());
                    received.add(e);
                }, new touchline.app.SystemClock()).start();
        send(status(4, Framing.LENGTH_PREFIX));
        next();
        String in = threads.poll(touchline.testing.Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
        assertNotNull(in);
        String transportThread = in.substring("IN ".length());

        assertTrue(transport.send(4, new MessageCodec(new MessageKinds()).optionListRequest()).isSent());
        assertEquals(1, transport.counters().datagramsOut(), "counted when accepted");
        assertEquals(Direction.OUT, next().direction());
        String out = threads.poll(touchline.testing.Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
        assertEquals("OUT " + transportThread, out, "published on the transport's event loop");
        assertNotEquals(Thread.currentThread().getName(), transportThread);
        DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
        robot.receive(p); // and written
    }

    @Test
    void withATeamKeyAForgedDatagramIsDecodedButNeverPublishedNorLearnedAndItsCounterIsNotTaken() throws Exception {
        useTeamKey();
        InetSocketAddress source = (InetSocketAddress) robot.getLocalSocketAddress();
        transport.setReading(false);
        // a well-formed status claiming robot 3 under another team's key, then one with a bad tag and a
        // high counter: both decode, neither may be published, teach the robot's address or take its counter
        send(new MessageTag(new TeamKey(new byte[]{
                1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29,
                30, 31, 32})).append(MessageTag.FROM_ROBOT, 3, 50, status(3, Framing.LEGACY)));
        byte[] badTag = tagged(3, 100, status(3, Framing.LEGACY));
        badTag[badTag.length - 1] ^= 1;
        send(badTag);
        send(tagged(3, 7, status(3, Framing.LEGACY))); // the robot's own: below the forger's counter, still taken
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
    void withATeamKeyAForgedDatagramAloneTeachesNoAddress() throws Exception {
        useTeamKey();
        byte[] badTag = tagged(4, 1, status(4, Framing.LEGACY));
        badTag[badTag.length - 1] ^= 1;
        send(badTag);
        assertEquals(Authenticity.FORGED, nextIn().authenticity());
        assertTrue(transport.peers().peer(4).isEmpty(), "no way back to a robot only a forger spoke for");
        assertEquals(1, transport.counters().forgedIn());
    }

    @Test
    void withATeamKeySegmentsAndDatagramsWithTheRobotsNextCountersAreAcceptedInArrivalOrderAndAReplayIsRefused()
            throws Exception {
        ReliableStreamHandler reliable = useTeamKeyAndReliableStream();
        InetSocketAddress source = (InetSocketAddress) robot.getLocalSocketAddress();
        ReliableSession session = reliable.open(source);
        transport.setReading(false);
        send(tagged(3, 1, status(3, Framing.LEGACY))); // teaches robot 3's address: the segments' robot
        send(tagged(3, 2, ReliableSessionTest.segment(0, "first ")));
        send(tagged(3, 3, status(3, Framing.LEGACY)));
        send(tagged(3, 4, ReliableSessionTest.segment(1, "second")));
        send(tagged(3, 4, ReliableSessionTest.segment(1, "second"))); // the same segment again: counter replayed
        send(tagged(3, 3, status(3, Framing.LEGACY))); // a datagram replayed behind the segment
        send(tagged(3, 5, status(3, Framing.LEGACY)));
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
