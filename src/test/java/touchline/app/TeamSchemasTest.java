package touchline.app;

import com.google.protobuf.DescriptorProtos.DescriptorProto;
import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageKinds;
import touchline.record.RecordingException;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Loading a team's descriptor set: what decodes afterwards, what is refused and why. */
public class TeamSchemasTest {

    @TempDir
    Path dir;

    /** {@code <name>.proto}: message Payload { float x = 1; } extend fumanoid.Message { Payload <name> = <number>; } */
    public static FileDescriptorSet teamSet(String name, int number) {
        FileDescriptorProto team = FileDescriptorProto.newBuilder().setName(name + ".proto").setPackage(name)
                .addDependency("fumanoid.proto")
                .addMessageType(DescriptorProto.newBuilder().setName("Payload").addField(FieldDescriptorProto.newBuilder()
                        .setName("x").setNumber(1).setType(FieldDescriptorProto.Type.TYPE_FLOAT)
                        .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL)))
                .addExtension(FieldDescriptorProto.newBuilder().setName(name).setNumber(number)
                        .setExtendee(".fumanoid.Message").setTypeName("." + name + ".Payload")
                        .setType(FieldDescriptorProto.Type.TYPE_MESSAGE).setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        return FileDescriptorSet.newBuilder().addFile(Fumanoid.getDescriptor().toProto()).addFile(team).build();
    }

    private Path write(String file, FileDescriptorSet set) throws Exception {
        Path p = dir.resolve(file);
        Files.write(p, set.toByteArray());
        return p;
    }

    @Test
    void extensionsDecodeByNameAfterLoading() throws Exception {
        MessageKinds kinds = new MessageKinds();
        TeamSchemas schemas = new TeamSchemas(kinds);
        TeamSchemas.Outcome o = schemas.load(write("team.desc", teamSet("teamBall", 1042)));
        assertEquals(1, o.extensions().size());
        assertTrue(o.extensions().get(0).startsWith("teamBall = 1042  (teamBall.Payload"), o.extensions().get(0));
        assertTrue(o.refusals().isEmpty(), o.refusals()::toString);
        assertEquals(1042, kinds.byName("teamBall").orElseThrow().getNumber());

        TeamSchemas.Outcome again = schemas.load(dir.resolve("team.desc"));
        assertTrue(again.extensions().isEmpty());
        assertTrue(again.refusals().get(0).contains("nothing new"), again.refusals()::toString);
    }

    @Test
    void aTakenExtensionNumberIsRefusedWithItsReason() throws Exception {
        MessageKinds kinds = new MessageKinds();
        TeamSchemas schemas = new TeamSchemas(kinds);
        schemas.load(write("a.desc", teamSet("teamBall", 1042)));
        TeamSchemas.Outcome o = schemas.load(write("b.desc", teamSet("otherBall", 1042)));
        assertTrue(o.extensions().isEmpty(), o.extensions()::toString);
        assertTrue(o.refusals().get(0).contains("is taken by teamBall.teamBall"), o.refusals()::toString);
        assertTrue(kinds.byName("otherBall").isEmpty());
    }

    @Test
    void notADescriptorSetGivesAClearMessage() throws Exception {
        Path junk = dir.resolve("junk.pb");
        Files.write(junk, new byte[]{(byte) 0xFF, 1, 2});
        RecordingException e = assertThrows(RecordingException.class, () -> new TeamSchemas(new MessageKinds()).load(junk));
        assertTrue(e.getMessage().contains("not a protobuf descriptor set"), e.getMessage());
    }
}
