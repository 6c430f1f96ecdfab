package touchline.protocol;

import com.google.protobuf.DescriptorProtos.DescriptorProto;
import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.Descriptors.FieldDescriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class DebugDataTest {

    private final MessageKinds kinds = new MessageKinds();
    private final DebugData data = new DebugData(kinds);

    @Test
    void everyOwnDataKindGivesItsOptionThroughTheFastPathAsReflectionWould() {
        Fumanoid.Message.Builder b = Fumanoid.Message.newBuilder().setRobotID(2);
        var samples = java.util.List.of(
                b.clone().setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("t").build()),
                b.clone().setExtension(Fumanoid.debugPlot, Fumanoid.DebugPlot.newBuilder().setOption("p").build()),
                b.clone().setExtension(Fumanoid.debugTable, Fumanoid.DebugTable.newBuilder().setOption("tb").build()),
                b.clone().setExtension(Fumanoid.regionGrowing, Fumanoid.RegionGrowing.newBuilder().setOption("r").build()),
                b.clone().setExtension(Fumanoid.grid, Fumanoid.Grid.newBuilder().setOption("g").build()),
                b.clone().setExtension(Fumanoid.relativePositions,
                        Fumanoid.RelativePositions.newBuilder().setOption("rp").build()),
                b.clone().setExtension(Fumanoid.debugImage, Fumanoid.DebugImage.newBuilder().setOption("i").build()),
                b.clone().setExtension(Fumanoid.fieldObjects, Fumanoid.FieldObjects.newBuilder().setOption("f").build()));
        for (Fumanoid.Message.Builder s : samples) {
            Fumanoid.Message m = s.buildPartial();
            FieldDescriptor ext = m.getAllFields().keySet().stream().filter(FieldDescriptor::isExtension).findFirst()
                    .orElseThrow();
            com.google.protobuf.Message inner = (com.google.protobuf.Message) m.getField(ext);
            String viaReflection = (String) inner.getField(inner.getDescriptorForType().findFieldByName("option"));
            assertEquals(viaReflection, data.optionOf(ext.getName(), m), ext.getName());
            assertTrue(DebugData.isOwnKind(ext.getName()));
        }
    }

    @Test
    void messagesWithoutDataOrOptionGiveNull() {
        Fumanoid.Message status = Fumanoid.Message.newBuilder().setRobotID(1)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(3).build()).build();
        assertNull(data.optionOf("status", status));
        assertNull(data.optionOf("debugText", status), "the kind says text, the message has none");
        assertNull(data.optionOf("ext#1042", status));
        assertTrue(DebugData.isOwnKind("status"));
        assertFalse(DebugData.isOwnKind("teamBall"));
    }

    @Test
    void aTeamsOwnTypeIsReadThroughReflection() throws Exception {
        FileDescriptorProto team = FileDescriptorProto.newBuilder().setName("team.proto").setPackage("team")
                .addDependency("fumanoid.proto")
                .addMessageType(DescriptorProto.newBuilder().setName("TeamBall")
                        .addField(FieldDescriptorProto.newBuilder().setName("option").setNumber(1)
                                .setType(FieldDescriptorProto.Type.TYPE_STRING)
                                .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL)))
                .addExtension(FieldDescriptorProto.newBuilder().setName("teamBall").setNumber(1042)
                        .setExtendee(".fumanoid.Message").setTypeName(".team.TeamBall")
                        .setType(FieldDescriptorProto.Type.TYPE_MESSAGE).setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        FileDescriptor file = FileDescriptor.buildFrom(team, new FileDescriptor[]{Fumanoid.getDescriptor()});
        assertTrue(kinds.add(file).isEmpty());
        FieldDescriptor ext = file.findExtensionByName("teamBall");
        DynamicMessage ball = DynamicMessage.newBuilder(file.findMessageTypeByName("TeamBall"))
                .setField(file.findMessageTypeByName("TeamBall").findFieldByName("option"), "team.ball").build();
        Fumanoid.Message m = Fumanoid.Message.parseFrom(Fumanoid.Message.newBuilder().setRobotID(1)
                .setField(ext, ball).build().toByteArray(), kinds.registry());
        assertEquals("team.ball", data.optionOf("teamBall", m));
    }
}
