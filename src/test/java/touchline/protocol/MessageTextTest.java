package touchline.protocol;

import com.google.protobuf.ByteString;
import com.google.protobuf.CodedOutputStream;
import com.google.protobuf.Message;
import com.google.protobuf.TextFormat;
import com.google.protobuf.UnknownFieldSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import touchline.proto.Fumanoid;
import touchline.proto.Nao;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.*;

class MessageTextTest {

    private final MessageCodec codec = new MessageCodec(new MessageKinds());
    private final MessageText text = new MessageText();

    private static Fumanoid.Message status(UnknownFieldSet unknownInStatus) {
        return Fumanoid.Message.newBuilder().setRobotID(3).setExtension(Fumanoid.status, Fumanoid.Status.newBuilder()
                .setTimestamp(1234).setTeamID(13).setRobotName("fu\"3\n").setRobotPositionBelief(0.5)
                .setRobotPosition(Fumanoid.Position.newBuilder().setX(1.5f).setY(-2).setTheta(3))
                .setUnknownFields(unknownInStatus).build()).build();
    }

    private Message decoded(Message m) {
        return assertInstanceOf(MessageResult.Decoded.class, codec.decode(m.toByteArray())).message();
    }

    @Test
    void knownFieldsAndUnknownFieldsInsideThemLookAsProtobufPrintsThem() {
        UnknownFieldSet unknown = UnknownFieldSet.newBuilder()
                .addField(99, UnknownFieldSet.Field.newBuilder().addVarint(-1).addFixed32(7).addFixed64(8).build())
                .addField(100, UnknownFieldSet.Field.newBuilder()
                        .addLengthDelimited(ByteString.copyFrom(new byte[]{0x08, 0x05}))
                        .addLengthDelimited(ByteString.copyFromUtf8("\u00ffnot a message")).build())
                .build();
        Fumanoid.DebugOptionList.Builder list = Fumanoid.DebugOptionList.newBuilder();
        for (int i = 0; i < 3; i++) {
            list.addOptions(Fumanoid.DebugOption.newBuilder().setName("o" + i).setKind(i).setEnabled(i == 1));
        }
        Nao.MixedValue.Builder mixed = Nao.MixedValue.newBuilder().setString("leaf").setBinary(ByteString.copyFrom(new byte[]{0, 1, (byte) 0xff}));
        for (int i = 0; i < 5; i++) {
            mixed = Nao.MixedValue.newBuilder().setInt(i).setFloat(i / 3f).setBool(true).addArray(mixed).addArray(mixed);
        }
        for (Message m : new Message[]{decoded(status(unknown)), decoded(status(UnknownFieldSet.getDefaultInstance())),
                Fumanoid.Message.newBuilder().setRobotID(1).setExtension(Fumanoid.debugOptionList, list.build()).build(),
                Nao.HAWActorRPCResponse.newBuilder().setReturnval(mixed).setError("é").build()}) {
            assertEquals(TextFormat.printer().printToString(m), text.render(m));
        }
    }

    /** {@code depth} levels of field 1 inside field 1, as unknown field 100 of a Status. */
    private static byte[] statusWithNestedUnknown(int depth, byte[] innermost) throws IOException {
        byte[] inner = innermost;
        for (int i = 0; i < depth; i++) {
            ByteArrayOutputStream b = new ByteArrayOutputStream();
            CodedOutputStream out = CodedOutputStream.newInstance(b);
            out.writeByteArray(1, inner);
            out.flush();
            inner = b.toByteArray();
        }
        UnknownFieldSet unknown = UnknownFieldSet.newBuilder()
                .addField(100, UnknownFieldSet.Field.newBuilder().addLengthDelimited(ByteString.copyFrom(inner)).build()).build();
        return status(unknown).toByteArray();
    }

    @Test
    void unknownFieldsNestedDeepInsideAKnownMessageStopAtADepthMarker() throws IOException {
        // ~3.5 KB of nesting overflowed protobuf's printer's stack
        byte[] payload = statusWithNestedUnknown(1500, new byte[]{0x08, 0x01});
        assertTrue(payload.length < 6000);
        Message m = assertInstanceOf(MessageResult.Decoded.class, codec.decode(payload)).message();
        String rendered = assertDoesNotThrow(() -> text.render(m));
        assertTrue(rendered.contains("1: { … nested deeper than " + MessageText.MAX_DEPTH + " levels: "), rendered);
        assertTrue(rendered.contains("robotName: \"fu\\\"3\\n\""), "the known fields are still shown: " + rendered);
        assertFalse(rendered.contains("  ".repeat(MessageText.MAX_DEPTH + 1)), "no line indented deeper than the limit");
        assertDoesNotThrow(() -> text.renderLine(m));
    }

    @Test
    void knownMessagesNestedDeeperThanTheLimitStopAtADepthMarker() {
        Nao.MixedValue.Builder mixed = Nao.MixedValue.newBuilder().setString("leaf");
        for (int i = 0; i < 90; i++) {
            mixed = Nao.MixedValue.newBuilder().addArray(mixed);
        }
        String rendered = text.render(Nao.HAWActorRPCResponse.newBuilder().setReturnval(mixed).build());
        assertTrue(rendered.contains("array { … nested deeper than " + MessageText.MAX_DEPTH + " levels: "), rendered);
        assertFalse(rendered.contains("leaf"));
    }

    @Test
    void oneDatagramRendersToBoundedText() throws IOException {
        // 30 levels deep, then a run of tiny varints: every 2 bytes a line indented 60 spaces
        ByteArrayOutputStream varints = new ByteArrayOutputStream();
        for (int i = 0; i < 600; i++) {
            varints.write(0x08);
            varints.write(0x00);
        }
        byte[] payload = statusWithNestedUnknown(28, varints.toByteArray());
        byte[] datagram = new FrameCodec().encode(Framing.LENGTH_PREFIX, payload);
        assertTrue(datagram.length <= FrameCodec.MAX_DATAGRAM, "fits one datagram: " + datagram.length);
        Message m = assertInstanceOf(MessageResult.Decoded.class, codec.decode(payload)).message();
        String rendered = text.render(m);
        assertTrue(rendered.length() <= MessageText.MAX_CHARS + 200, "bounded: " + rendered.length());
        assertTrue(rendered.contains("… the text stops here, at " + MessageText.MAX_CHARS + " characters; the message is "
                + payload.length + " bytes"), rendered.substring(rendered.length() - 300));
        assertTrue(rendered.startsWith(TextFormat.printer().printToString(m).substring(0, 1000)), "the start is unchanged");
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD) // a guard only: the assertions below are the test
    void foldingLinesIsLinearInALongRunOfSpaces() {
        String spaces = " ".repeat(160_000);
        String folded = MessageText.foldLines("a" + spaces + "b \n\t c\n");
        assertEquals("a" + spaces + "b c", folded);
    }

    @Test
    void foldingLinesDoesWhatTheRegexDid() {
        Random random = new Random(11);
        char[] alphabet = {' ', '\t', '\n', '\r', '\f', 0x0B, 'x', 'y', '\u00a0', 0x01};
        for (int round = 0; round < 5000; round++) {
            StringBuilder s = new StringBuilder();
            int n = random.nextInt(12);
            for (int i = 0; i < n; i++) {
                s.append(alphabet[random.nextInt(alphabet.length)]);
            }
            String input = s.toString();
            assertEquals(input.replaceAll("\\s*\\n\\s*", " ").trim(), MessageText.foldLines(input), "for " + input.chars().boxed().toList());
        }
    }
}
