package touchline.protocol;

import com.google.protobuf.ByteString;
import com.google.protobuf.UnknownFieldSet;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import java.util.HexFormat;

import static org.junit.jupiter.api.Assertions.*;

class MessageCodecTest {

    private final MessageCodec codec = new MessageCodec(new MessageKinds());
    private final MessageText text = new MessageText();

    @Test
    void robotIdIsReadFromTheBytesAsTheParseReadsIt() {
        byte[] status = Fumanoid.Message.newBuilder().setRobotID(5)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build().toByteArray();
        assertEquals(5, MessageCodec.robotIdOf(status));
        // field 1 twice: the parse keeps the last one, so must the peek
        byte[] twice = HexFormat.of().parseHex("08030807");
        assertEquals(7, ((MessageResult.Decoded) codec.decode(twice)).message().getRobotID());
        assertEquals(7, MessageCodec.robotIdOf(twice));
        // a negative int32 is a ten-byte varint
        byte[] negative = Fumanoid.Message.newBuilder().setRobotID(-2).build().toByteArray();
        assertEquals(-2, MessageCodec.robotIdOf(negative));
    }

    @Test
    void noRobotIdWhereTheParseFindsNone() {
        byte[] withoutId = HexFormat.of().parseHex("1001");                // field 2 only
        assertInstanceOf(MessageResult.Malformed.class, codec.decode(withoutId));
        assertEquals(MessageCodec.NO_ROBOT_ID, MessageCodec.robotIdOf(withoutId));
        byte[] lengthDelimitedField1 = HexFormat.of().parseHex("0a0103");  // field 1 with the wrong wire type
        assertInstanceOf(MessageResult.Malformed.class, codec.decode(lengthDelimitedField1));
        assertEquals(MessageCodec.NO_ROBOT_ID, MessageCodec.robotIdOf(lengthDelimitedField1));
        assertEquals(MessageCodec.NO_ROBOT_ID, MessageCodec.robotIdOf(new byte[]{(byte) 0xff, (byte) 0xff, (byte) 0xff}));
        assertEquals(MessageCodec.NO_ROBOT_ID, MessageCodec.robotIdOf(HexFormat.of().parseHex("0803" + "0c")));  // stray end-group
    }

    @Test
    void unknownExtensionIsKeptAndShownFieldByField() {
        // robotID 4, extension 1042 { 1: 7, 2: "ok", 3: { 1: 150 } } -- a team's own type we do not know
        byte[] inner = UnknownFieldSet.newBuilder()
                .addField(1, UnknownFieldSet.Field.newBuilder().addVarint(7).build())
                .addField(2, UnknownFieldSet.Field.newBuilder().addLengthDelimited(ByteString.copyFromUtf8("ok")).build())
                .addField(3, UnknownFieldSet.Field.newBuilder().addLengthDelimited(
                        ByteString.copyFrom(HexFormat.of().parseHex("089601"))).build())
                .build().toByteArray();
        byte[] payload = Fumanoid.Message.newBuilder().setRobotID(4)
                .setUnknownFields(UnknownFieldSet.newBuilder().addField(1042,
                        UnknownFieldSet.Field.newBuilder().addLengthDelimited(ByteString.copyFrom(inner)).build()).build())
                .build().toByteArray();

        var decoded = assertInstanceOf(MessageResult.Decoded.class, codec.decode(payload));
        assertEquals(1042, decoded.extension());
        assertEquals("ext#1042", decoded.kind());
        String rendered = text.render(decoded.message());
        assertTrue(rendered.contains("robotID: 4"), rendered);
        assertTrue(rendered.contains("unknown extension 1042 {"), rendered);
        assertTrue(rendered.contains("field 1 (varint): 7"), rendered);
        assertTrue(rendered.contains("field 2 (bytes, 2): \"ok\""), rendered);
        assertTrue(rendered.contains("field 1 (varint): 150"), rendered);
    }

    @Test
    void anUnknownKindGetsItsNameOnceTheTeamFileIsLoaded() throws Exception {
        MessageKinds kinds = new MessageKinds();
        assertEquals("ext#1042", kinds.kindOf(1042));
        assertSame(kinds.kindOf(3), kinds.kindOf(3), "one String per kind");
        com.google.protobuf.DescriptorProtos.FileDescriptorProto team = com.google.protobuf.DescriptorProtos
                .FileDescriptorProto.newBuilder().setName("team.proto").setPackage("team").addDependency("fumanoid.proto")
                .addMessageType(com.google.protobuf.DescriptorProtos.DescriptorProto.newBuilder().setName("TeamBall"))
                .addExtension(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.newBuilder().setName("teamBall")
                        .setNumber(1042).setExtendee(".fumanoid.Message").setTypeName(".team.TeamBall")
                        .setType(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Type.TYPE_MESSAGE)
                        .setLabel(com.google.protobuf.DescriptorProtos.FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        var file = com.google.protobuf.Descriptors.FileDescriptor.buildFrom(team,
                new com.google.protobuf.Descriptors.FileDescriptor[]{Fumanoid.getDescriptor()});
        assertTrue(kinds.add(file).isEmpty());
        assertEquals("teamBall", kinds.kindOf(1042));
    }

    @Test
    void knownExtensionRendersAsText() {
        var decoded = assertInstanceOf(MessageResult.Decoded.class,
                codec.decode(codec.optionRequest("demo.text", true).toByteArray()));
        assertEquals("debugOptionRequest", decoded.kind());
        String rendered = text.renderLine(decoded.message());
        assertTrue(rendered.contains("[fumanoid.debugOptionRequest] { name: \"demo.text\" enable: true }"), rendered);
    }

    @Test
    void garbageIsMalformedWithReason() {
        var m = assertInstanceOf(MessageResult.Malformed.class, codec.decode(new byte[]{(byte) 0xff, (byte) 0xff, 0x01}));
        assertTrue(m.reason().startsWith("protobuf: "), m.reason());
    }

    @Test
    void missingRobotIdIsMalformed() {
        byte[] payload = HexFormat.of().parseHex("ba0100"); // only an empty status extension
        var m = assertInstanceOf(MessageResult.Malformed.class, codec.decode(payload));
        assertEquals("protobuf: message without the required robotID", m.reason());
    }
}
