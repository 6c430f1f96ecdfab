package touchline.protocol;

import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import java.io.IOException;
import java.io.InputStream;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;

/**
 * The match digest golden vector (golden/fumanoid/match-digest.bin, encoded by protoc from
 * match-digest.txt; the firmware's fw_test_digest builds the same bytes): Java's encoder gives
 * them byte for byte, and the console takes them apart into the Status and each item as its
 * own message, with the count of items left out.
 */
class MatchDigestGoldenTest {

    private final MessageKinds kinds = new MessageKinds();

    static byte[] golden() throws IOException {
        try (InputStream in = MatchDigestGoldenTest.class.getResourceAsStream("/golden/fumanoid/match-digest.bin")) {
            return in.readAllBytes();
        }
    }

    /** The golden digest built with protobuf-java's builders, from match-digest.txt's values. */
    static Fumanoid.Message expected() {
        Fumanoid.Status status = Fumanoid.Status.newBuilder().setTimestamp(123456).setTeamID(13).setTimeOnline(42)
                .setRobotPosition(Fumanoid.Position.newBuilder().setX(1000.5f).setY(-250f).setTheta(0.75f))
                .setRobotPositionBelief(0.8).setActiveAgent("SoccerAgent").setActiveRole("striker")
                .setCurrentState("playing").setRobotName("robot-3").setBatteryPercent(97).setGameState("PLAYING")
                .setGcOtherSource(0).build();
        Fumanoid.Message plot = Fumanoid.Message.newBuilder().setRobotID(3).setExtension(Fumanoid.debugPlot,
                Fumanoid.DebugPlot.newBuilder().setOption("demo.plotter").setTimestamp(123456)
                        .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("sin").setValue(0.5))
                        .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("cos").setValue(-0.25)).build()).build();
        Fumanoid.Message field = Fumanoid.Message.newBuilder().setRobotID(3).setExtension(Fumanoid.fieldObjects,
                Fumanoid.FieldObjects.newBuilder().setOption("demo.field")
                        .addObjects(Fumanoid.RelativeObject.newBuilder().setLabel("ball").setX(1200f).setY(-300f))
                        .build()).build();
        return Fumanoid.Message.newBuilder().setRobotID(3).setExtension(Fumanoid.matchDigest,
                Fumanoid.MatchDigest.newBuilder().setStatus(status).addItems(plot).addItems(field).setOmitted(1).build())
                .build();
    }

    @Test
    void javaEncodesTheGoldenDigestByteForByte() throws IOException {
        byte[] datagram = new FrameCodec().encode(Framing.LENGTH_PREFIX, expected().toByteArray());
        assertArrayEquals(golden(), datagram);
        assertEquals(200, datagram.length);
    }

    @Test
    void theGoldenDigestComesApartIntoTheStatusAndEachItem() throws IOException {
        FrameResult.Frame frame = assertInstanceOf(FrameResult.Frame.class, new FrameCodec().decode(golden()));
        MessageResult.Decoded decoded = assertInstanceOf(MessageResult.Decoded.class,
                new MessageCodec(kinds).decode(frame.payload()));
        assertEquals("matchDigest", decoded.kind());
        assertEquals(51, decoded.extension());
        assertEquals(1, decoded.message().getExtension(Fumanoid.matchDigest).getOmitted());

        List<MatchDigestParts.Part> parts = new MatchDigestParts(kinds).of(decoded.message());
        assertEquals(List.of("status", "debugPlot", "fieldObjects"), parts.stream().map(MatchDigestParts.Part::kind).toList());
        assertEquals("PLAYING", parts.get(0).message().getExtension(Fumanoid.status).getGameState());
        assertEquals(3, parts.get(0).message().getRobotID());
        assertEquals(-0.25, parts.get(1).message().getExtension(Fumanoid.debugPlot).getSamples(1).getValue());
        assertEquals("ball", parts.get(2).message().getExtension(Fumanoid.fieldObjects).getObjects(0).getLabel());
        // each part is the message the robot would have streamed: it decodes on its own
        for (MatchDigestParts.Part p : parts) {
            MessageResult.Decoded alone = assertInstanceOf(MessageResult.Decoded.class, new MessageCodec(kinds).decode(p.bytes()));
            assertEquals(p.kind(), alone.kind());
            assertEquals(p.message(), alone.message());
        }
    }

    @Test
    void aMessageWithoutADigestHasNoParts() {
        Fumanoid.Message status = Fumanoid.Message.newBuilder().setRobotID(3)
                .setExtension(Fumanoid.status, Fumanoid.Status.getDefaultInstance()).build();
        assertEquals(List.of(), new MatchDigestParts(kinds).of(status));
    }

    /**
     * A digest cut short (a lost tail fragment, a robot's bug) is a malformed datagram with its
     * reason, never an exception and never a part made up: whatever decodes still comes apart into
     * parts that decode on their own.
     */
    @Test
    void aDigestCutAtAnyLengthIsMalformedOrComesApartWhole() throws IOException {
        FrameResult.Frame frame = assertInstanceOf(FrameResult.Frame.class, new FrameCodec().decode(golden()));
        byte[] payload = frame.payload();
        int malformed = 0;
        for (int n = 1; n < payload.length; n++) {
            MessageResult r = new MessageCodec(kinds).decode(java.util.Arrays.copyOf(payload, n));
            if (r instanceof MessageResult.Malformed m) {
                malformed++;
                org.junit.jupiter.api.Assertions.assertFalse(m.reason().isBlank(), "a reason for the cut at " + n);
            } else if (r instanceof MessageResult.Decoded d) {
                for (MatchDigestParts.Part p : new MatchDigestParts(kinds).of(d.message())) {
                    assertInstanceOf(MessageResult.Decoded.class, new MessageCodec(kinds).decode(p.bytes()),
                            "part " + p.kind() + " of the cut at " + n);
                }
            }
        }
        org.junit.jupiter.api.Assertions.assertTrue(malformed > payload.length / 2,
                "most cuts end inside a field: " + malformed + " of " + (payload.length - 1));
    }
}
