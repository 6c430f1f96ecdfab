package touchline.record;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class RecordingRoundTripTest {

    @TempDir
    Path dir;

    @Test
    void everyEnvelopeComesBackEqualInOrderWithItsTime() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 40);
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.IN, Channel.RELIABLE_STREAM,
                InetSocketAddress.createUnresolved("robot4.local", 4000), 4, "segment", null, new byte[]{1, 2, 3}, null));
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.OUT, Channel.NAO_CAMERA,
                null, Envelope.NO_ROBOT, "jpeg", null, new byte[]{(byte) 0xFF, (byte) 0xD8, 0, 0}, null));
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.IN, Channel.FUMANOID,
                null, Envelope.NO_ROBOT, "malformed", null, new byte[0], "empty datagram"));
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.IN, Channel.TEAM_MESSAGE,
                new InetSocketAddress("127.0.0.1", 40013), Envelope.NO_ROBOT, "team.message", null, new byte[]{7, 7, 7}, null));
        byte[] flagged = sent.stream().filter(e -> e.kind().equals("status") && e.robotId() == 1).findFirst()
                .orElseThrow().raw().clone();
        flagged[2] = 1; // legacy header with a flag set: kept as raw bytes, still replayed exactly
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.IN, Channel.FUMANOID, null, 1,
                "status", Fumanoid.Message.getDefaultInstance(), flagged, null));
        // a replayed message of another tool's channel, recorded again: its bytes come back as they were
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 2, Direction.IN, Channel.FOREIGN, null,
                Envelope.NO_ROBOT, "/their/score", null, "{\"home\": 1}".getBytes(java.nio.charset.StandardCharsets.UTF_8),
                null));
        // a bridged ROS 2 robot's message (no schema known to this writer: kept as its bytes under /bridge/1001/…)
        sent.add(new Envelope(sent.get(sent.size() - 1).timeMicros() + 1, Direction.IN, Channel.BRIDGE,
                InetSocketAddress.createUnresolved("booster-1.local", 8765), 1001, "/robot_state", null,
                "{\"game_state\": \"READY\"}".getBytes(java.nio.charset.StandardCharsets.UTF_8), null));
        Set<Channel> channels = sent.stream().map(Envelope::channel).collect(Collectors.toCollection(() -> EnumSet.noneOf(Channel.class)));
        assertEquals(EnumSet.allOf(Channel.class), channels, "the fixture covers every wire channel");

        Path file = dir.resolve("s.mcap");
        RecordingFixture.write(file, sent, EnvelopeWriter.Options.defaults().withSplit(0, 0));
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertEquals(sent.size(), back.size());
            for (int i = 0; i < sent.size(); i++) {
                assertEquals(sent.get(i), back.get(i), "envelope " + i);
            }
            assertTrue(r.problems().isEmpty(), r.problems().toString());
            assertTrue(r.mcap().indexed());
            assertEquals(sent.size(), r.mcap().messageCount());
            assertEquals(sent.get(0).timeMicros(), r.startMicros());
            assertEquals(sent.get(sent.size() - 1).timeMicros(), r.endMicros());
        }
    }

    /**
     * With a team key every robot datagram ends in a 32-byte trailer: recorded as its protobuf
     * message all the same (other tools decode it; a replay and a remote viewer get the robot's
     * data), without the trailer; a forgery (no message) is kept whole with its reason.
     */
    @Test
    void aTaggedDatagramIsRecordedAsItsMessageWithoutItsTrailerAndAForgeryWhole() throws Exception {
        Envelope status = RecordingFixture.team(1, 1).stream().filter(e -> e.kind().equals("status")).findFirst()
                .orElseThrow();
        touchline.security.MessageTag tag = new touchline.security.MessageTag(new touchline.security.TeamKey(new byte[32]));
        byte[] tagged = tag.append(touchline.security.MessageTag.FROM_ROBOT, 1, 42, status.raw());
        byte[] forgedBytes = tag.append(touchline.security.MessageTag.FROM_ROBOT, 1, 43, status.raw());
        forgedBytes[forgedBytes.length - 1] ^= 1;
        List<Envelope> sent = List.of(
                new Envelope(status.timeMicros(), Direction.IN, Channel.FUMANOID, status.peer(), 1, "status",
                        status.message(), tagged, null, touchline.transport.Origin.LIVE,
                        touchline.security.Authenticity.VERIFIED),
                new Envelope(status.timeMicros() + 1, Direction.IN, Channel.FUMANOID, status.peer(), 1, "forged", null,
                        forgedBytes, "forged: bad tag (claims robot 1)", touchline.transport.Origin.LIVE,
                        touchline.security.Authenticity.FORGED));
        Path file = dir.resolve("tagged.mcap");
        RecordingFixture.write(file, sent, EnvelopeWriter.Options.defaults());
        try (Recording r = Recording.open(file)) {
            McapReader.ChannelInfo channel = r.mcap().channels().values().stream()
                    .filter(c -> c.topic().equals("/robot/1/status")).findFirst().orElseThrow();
            assertEquals("protobuf", channel.messageEncoding());
            assertEquals("payload", channel.metadata().get("touchline.layout"));
            assertEquals("LEGACY", channel.metadata().get("touchline.framing"));
            List<Envelope> back = RecordingFixture.readAll(r);
            assertEquals(2, back.size());
            assertEquals(status.message(), back.get(0).message(), "the robot's data comes back decoded");
            assertEquals(status.raw().length, back.get(0).raw().length, "without the trailer");
            assertTrue(java.util.Arrays.equals(status.raw(), back.get(0).raw()));
            assertTrue(java.util.Arrays.equals(forgedBytes, back.get(1).raw()), "the forgery whole");
            assertEquals("forged: bad tag (claims robot 1)", back.get(1).error());
            assertTrue(r.problems().isEmpty(), r.problems().toString());
        }
    }

    @Test
    void envelopesThatDifferOnlyInPeerFramingOrDirectionKeepTheirOwnChannels() throws Exception {
        // the writer's channel cache compares fields in place; every one of them must count
        List<Envelope> team = RecordingFixture.team(1, 2);
        Envelope status = team.stream().filter(e -> e.kind().equals("status")).findFirst().orElseThrow();
        byte[] payload = java.util.Arrays.copyOfRange(status.raw(), 12, status.raw().length);
        byte[] lengthFramed = new touchline.protocol.FrameCodec().encode(touchline.protocol.Framing.LENGTH_PREFIX, payload);
        // another robot address, same port: the case a cache keyed by port alone would merge
        java.net.InetSocketAddress otherPort = new java.net.InetSocketAddress(
                java.net.InetAddress.getByAddress(new byte[]{10, 0, 0, 99}), status.peer().getPort());
        List<Envelope> sent = new java.util.ArrayList<>();
        for (int i = 0; i < 40; i++) {
            long t = status.timeMicros() + i;
            sent.add(switch (i % 4) {
                case 0 -> new Envelope(t, Direction.IN, Channel.FUMANOID, status.peer(), status.robotId(), status.kind(),
                        status.message(), status.raw(), null);
                case 1 -> new Envelope(t, Direction.IN, Channel.FUMANOID, otherPort, status.robotId(), status.kind(),
                        status.message(), status.raw(), null);
                case 2 -> new Envelope(t, Direction.IN, Channel.FUMANOID, status.peer(), status.robotId(), status.kind(),
                        status.message(), lengthFramed, null);
                default -> new Envelope(t, Direction.OUT, Channel.FUMANOID, status.peer(), status.robotId(), status.kind(),
                        status.message(), status.raw(), null);
            });
        }
        Path file = dir.resolve("channels.mcap");
        RecordingFixture.write(file, sent, EnvelopeWriter.Options.defaults());
        try (Recording r = Recording.open(file)) {
            assertEquals(sent, RecordingFixture.readAll(r));
        }
    }

    @Test
    void decodedMessagesComeBackAndTheRobotTimestampIsThePublishTime() throws Exception {
        List<Envelope> sent = RecordingFixture.team(1, 2);
        Path file = dir.resolve("m.mcap");
        RecordingFixture.write(file, sent, EnvelopeWriter.Options.defaults());
        try (Recording r = Recording.open(file)) {
            Envelope status = RecordingFixture.readAll(r).stream().filter(e -> e.kind().equals("status")).findFirst().orElseThrow();
            Fumanoid.Message m = assertInstanceOf(Fumanoid.Message.class, status.message());
            long robotMillis = m.getExtension(Fumanoid.status).getTimestamp();
            McapReader.Cursor c = r.mcap().cursor(0);
            McapReader.McapMessage first = c.next();
            while (!r.mcap().channels().get(first.channelId()).topic().equals("/robot/1/status")) {
                first = c.next();
            }
            assertEquals(robotMillis * 1_000_000L, first.publishTime());
            assertEquals(status.timeMicros() * 1000, first.logTime());
        }
        Envelope malformed = sent.stream().filter(Envelope::isMalformed).findFirst().orElse(null);
        assertNull(malformed, "a 2-second fixture has no malformed datagram (they come at second 7)");
    }

    @Test
    void splitsBySizeAndByTimeIntoFilesThatTogetherHoldEverything() throws Exception {
        List<Envelope> sent = RecordingFixture.team(3, 30);
        Path file = dir.resolve("split.mcap");
        List<Path> files;
        try (EnvelopeWriter w = new EnvelopeWriter(file, new EnvelopeWriter.Options(0, 10_000_000L, 64 * 1024, List.of()))) {
            for (Envelope e : sent) {
                w.write(e);
            }
            files = w.files();
        }
        assertEquals(List.of(file, dir.resolve("split-001.mcap"), dir.resolve("split-002.mcap")), files);
        int total = 0;
        for (Path f : files) {
            try (Recording r = Recording.open(f)) {
                List<Envelope> part = RecordingFixture.readAll(r);
                assertEquals(sent.subList(total, total + part.size()), part);
                assertTrue(r.durationMicros() < 10_000_000L);
                total += part.size();
            }
        }
        assertEquals(sent.size(), total);

        Path bySize = dir.resolve("size.mcap");
        try (EnvelopeWriter w = new EnvelopeWriter(bySize, new EnvelopeWriter.Options(50_000, 0, 8 * 1024, List.of()))) {
            for (Envelope e : sent) {
                w.write(e);
            }
            files = w.files();
        }
        assertTrue(files.size() > 2, "several files of about 50 kB");
        for (Path f : files) {
            assertTrue(Files.size(f) < 80_000, f + " is " + Files.size(f));
        }
    }

    @Test
    void cameraFramesAreThinnedToTheConfiguredRate() throws Exception {
        List<Envelope> frames = new java.util.ArrayList<>();
        for (int i = 0; i < 300; i++) { // 30 frames a second for ten seconds
            frames.add(new Envelope(1_000_000L + i * 33_333L, Direction.IN, Channel.NAO_CAMERA, null, Envelope.NO_ROBOT,
                    "jpeg", null, new byte[]{(byte) 0xFF, (byte) 0xD8, (byte) i}, null));
        }
        Path file = dir.resolve("camera.mcap");
        long thinned;
        try (EnvelopeWriter w = new EnvelopeWriter(file, EnvelopeWriter.Options.defaults().withCameraRate(5))) {
            for (Envelope e : frames) {
                w.write(e);
            }
            thinned = w.thinnedFrames();
        }
        try (Recording r = Recording.open(file)) {
            List<Envelope> back = RecordingFixture.readAll(r);
            assertEquals(50, back.size(), "five frames a second");
            assertEquals(250, thinned);
            assertEquals(frames.get(0), back.get(0));
        }
    }

    /**
     * Issue 38: each channel says where its envelopes came from ({@code touchline.origin}), a
     * field other tools ignore: a status heard live and the same robot's status from a remote
     * Touchline go on two channels and come back with their origin; a file without the field
     * (before issue 38) reads as live.
     */
    @Test
    void eachChannelSaysTheOriginOfItsEnvelopes() throws Exception {
        Envelope live = RecordingFixture.team(1, 1).stream().filter(e -> e.kind().equals("status")).findFirst()
                .orElseThrow();
        Envelope remote = new Envelope(live.timeMicros() + 1, live.direction(), live.channel(), live.peer(),
                live.robotId(), live.kind(), live.message(), live.raw(), null, touchline.transport.Origin.REMOTE);
        Path file = dir.resolve("origins.mcap");
        RecordingFixture.write(file, List.of(live, remote), EnvelopeWriter.Options.defaults());
        try (Recording r = Recording.open(file)) {
            List<String> origins = r.mcap().channels().values().stream()
                    .map(c -> c.topic() + " " + c.metadata().get("touchline.origin")).sorted().toList();
            assertEquals(List.of("/robot/1/status live", "/robot/1/status remote"), origins);
            assertEquals(List.of(live, remote), RecordingFixture.readAll(r));
        }
        assertEquals(touchline.transport.Origin.LIVE, EnvelopeLayout.Key.fromMetadata(java.util.Map.of(
                "touchline.direction", "IN", "touchline.channel", "FUMANOID", "touchline.robot", "1",
                "touchline.kind", "status", "touchline.layout", "raw")).origin(),
                "a channel without touchline.origin holds live envelopes");
    }
}
