package touchline.record;

import com.google.protobuf.DescriptorProtos.DescriptorProto;
import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.protocol.MessageKinds;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A team's own types: loaded from a descriptor set, carried in recordings, decoded on replay. */
class SchemaSetTest {

    @TempDir
    Path dir;

    /** team.proto: message TeamBall { optional float x = 1; } extend fumanoid.Message { TeamBall teamBall = 1042; } */
    static FileDescriptorSet teamDescriptorSet() {
        FileDescriptorProto team = FileDescriptorProto.newBuilder().setName("team.proto").setPackage("team")
                .addDependency("fumanoid.proto")
                .addMessageType(DescriptorProto.newBuilder().setName("TeamBall").addField(FieldDescriptorProto.newBuilder()
                        .setName("x").setNumber(1).setType(FieldDescriptorProto.Type.TYPE_FLOAT)
                        .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL)))
                .addExtension(FieldDescriptorProto.newBuilder().setName("teamBall").setNumber(1042)
                        .setExtendee(".fumanoid.Message").setTypeName(".team.TeamBall")
                        .setType(FieldDescriptorProto.Type.TYPE_MESSAGE).setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        return FileDescriptorSet.newBuilder().addFile(Fumanoid.getDescriptor().toProto()).addFile(team).build();
    }

    @Test
    void loadsAProtocDescriptorSetOntoTheCompiledTypes() throws Exception {
        Path desc = dir.resolve("team.desc");
        Files.write(desc, teamDescriptorSet().toByteArray());
        SchemaSet set = new SchemaSet();
        List<FileDescriptor> added = set.load(desc);
        assertEquals(1, added.size());
        FieldDescriptor ext = added.get(0).findExtensionByName("teamBall");
        assertTrue(ext.getContainingType() == Fumanoid.Message.getDescriptor(), "extends the compiled Message");
        assertEquals(added, set.teamFiles());
    }

    @Test
    void badDescriptorSetsGiveClearMessages() throws Exception {
        Path junk = dir.resolve("junk.desc");
        Files.write(junk, new byte[]{(byte) 0xFF, 1, 2});
        assertTrue(assertThrows(RecordingException.class, () -> new SchemaSet().load(junk)).getMessage()
                .contains("not a protobuf descriptor set"));
        FileDescriptorSet missingImport = FileDescriptorSet.newBuilder()
                .addFile(teamDescriptorSet().getFile(1).toBuilder().setDependency(0, "other.proto")).build();
        assertTrue(assertThrows(RecordingException.class, () -> new SchemaSet().add(missingImport)).getMessage()
                .contains("imports other.proto"));
    }

    @Test
    void aRecordingCarriesTheTeamTypesAndAFreshConsoleDecodesThem() throws Exception {
        FileDescriptor team = new SchemaSet().add(teamDescriptorSet()).get(0);
        FieldDescriptor ext = team.findExtensionByName("teamBall");
        DynamicMessage ball = DynamicMessage.newBuilder(ext.getMessageType())
                .setField(ext.getMessageType().findFieldByName("x"), 1.5f).build();
        Fumanoid.Message message = Fumanoid.Message.newBuilder().setRobotID(4).setField(ext, ball).build();
        byte[] raw = new FrameCodec().encode(Framing.LENGTH_PREFIX, message.toByteArray());
        Envelope sent = new Envelope(5_000_000L, Direction.IN, Channel.FUMANOID, null, 4, "teamBall", message, raw, null);
        Path file = dir.resolve("team.mcap");
        RecordingFixture.write(file, List.of(sent), EnvelopeWriter.Options.defaults());

        MessageKinds fresh = new MessageKinds();
        try (Recording r = Recording.open(file, fresh)) {
            assertEquals(1, r.schemas().size());
            assertTrue(r.schemas().get(0).getFileList().stream().anyMatch(f -> f.getName().equals("team.proto")));
            Envelope back = RecordingFixture.readAll(r).get(0);
            assertEquals(sent, back);
            assertEquals("teamBall", fresh.kindOf(1042));
            assertTrue(back.message().toString().contains("x: 1.5"), back.message().toString());
        }
    }
}
