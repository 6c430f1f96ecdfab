package touchline.model.store;

import com.google.protobuf.DescriptorProtos.DescriptorProto;
import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import org.junit.jupiter.api.Test;
import touchline.proto.Fumanoid;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.net.InetSocketAddress;
import java.util.List;

import static org.junit.jupiter.api.Assertions.*;

/** Plot anything: field paths from descriptors, series per robot, bounded rings, CSV; no JavaFX. */
class FieldPlotTest {

    private final MessageKinds kinds = new MessageKinds();
    private final MessageCodec codec = new MessageCodec(kinds);
    private final FieldPlot plot = new FieldPlot(kinds, 4, 0);

    private void receive(long micros, int robot, Fumanoid.Message built, boolean out) {
        MessageResult r = codec.decode(built.toByteArray());
        MessageResult.Decoded d = (MessageResult.Decoded) r;
        plot.accept(new Envelope(micros, out ? Direction.OUT : Direction.IN, Channel.FUMANOID,
                new InetSocketAddress("127.0.0.1", 4000 + robot), robot, d.kind(), d.message(), new byte[1], null));
    }

    private void status(long micros, int robot, int battery, double x) {
        receive(micros, robot, Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setBatteryPercent(battery)
                        .setRobotPosition(Fumanoid.Position.newBuilder().setX((float) x)).build()).build(), false);
    }

    @Test
    void offersTheNumericLeavesOfEveryKindSeenByTheirPaths() {
        assertEquals(List.of(), plot.paths(""), "nothing seen, nothing offered");
        status(1_000_000, 3, 80, 1.5);
        List<String> paths = plot.paths("");
        assertTrue(paths.containsAll(List.of("status:batteryPercent", "status:robotPosition.x", "status:teamID")), paths.toString());
        assertFalse(paths.contains("status:robotName"), "a string is no number");
        assertEquals(List.of("status:robotPosition.x"), plot.paths("POSITION.X"));
    }

    @Test
    void severalRobotsAndFieldsInOnePlotBoundedAndAsCsv() {
        status(1_000_000, 3, 80, 1.5);
        assertTrue(plot.add(3, "status:batteryPercent"));
        assertTrue(plot.add(4, "status:batteryPercent"));
        assertTrue(plot.add(3, "status:robotPosition.x"));
        assertFalse(plot.add(3, "status:robotName"), "not numeric");
        assertFalse(plot.add(3, "status:nothing"), "no such field");
        assertFalse(plot.add(3, "status:batteryPercent"), "already plotted");
        long v = plot.version();
        status(2_000_000, 3, 79, 2.0);
        status(2_500_000, 4, 60, 7.0);
        receive(2_600_000, 4, Fumanoid.Message.newBuilder().setRobotID(4).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setBatteryPercent(1).build()).build(), true); // sent, not heard
        assertTrue(plot.version() > v);
        List<PlotStore.SeriesData> s = plot.snapshot();
        assertEquals(List.of("robot 3 status:batteryPercent", "robot 4 status:batteryPercent",
                "robot 3 status:robotPosition.x"), s.stream().map(PlotStore.SeriesData::name).toList());
        assertEquals(1, s.get(0).count());
        assertEquals(79, s.get(0).y()[0]);
        assertEquals(60, s.get(1).y()[0]);
        assertEquals("""
                time_s,robot 3 status:batteryPercent,robot 4 status:batteryPercent,robot 3 status:robotPosition.x
                2.000000,79,,2
                2.500000,,60,
                """, plot.csv());
        for (int i = 0; i < 10; i++) {
            status(3_000_000 + i * 100_000L, 3, 50 + i, 0);
        }
        assertEquals(4, plot.snapshot().get(0).count(), "a ring of the last points");
        assertEquals(59, plot.snapshot().get(0).y()[3]);
    }

    @Test
    void aTeamsOwnTypeLoadedAtRunTimeIsPlottedToo() throws Exception {
        FileDescriptorProto team = FileDescriptorProto.newBuilder().setName("team.proto").setPackage("team")
                .addDependency("fumanoid.proto")
                .addMessageType(DescriptorProto.newBuilder().setName("Kick")
                        .addField(FieldDescriptorProto.newBuilder().setName("strength").setNumber(1)
                                .setType(FieldDescriptorProto.Type.TYPE_FLOAT)
                                .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL))
                        .addField(FieldDescriptorProto.newBuilder().setName("left").setNumber(2)
                                .setType(FieldDescriptorProto.Type.TYPE_BOOL)
                                .setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL)))
                .addExtension(FieldDescriptorProto.newBuilder().setName("teamKick").setNumber(1077)
                        .setExtendee(".fumanoid.Message").setTypeName(".team.Kick")
                        .setType(FieldDescriptorProto.Type.TYPE_MESSAGE).setLabel(FieldDescriptorProto.Label.LABEL_OPTIONAL))
                .build();
        FileDescriptor file = FileDescriptor.buildFrom(team, new FileDescriptor[]{Fumanoid.getDescriptor()});
        assertTrue(kinds.add(file).isEmpty());
        var type = file.findMessageTypeByName("Kick");
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(2).setField(file.findExtensionByName("teamKick"),
                DynamicMessage.newBuilder(type).setField(type.findFieldByName("strength"), 0.75f)
                        .setField(type.findFieldByName("left"), true).build()).build();
        receive(1_000_000, 2, m, false);
        assertEquals(List.of("teamKick:strength", "teamKick:left"), plot.paths("teamKick"));
        assertTrue(plot.add(2, "teamKick:strength"));
        assertTrue(plot.add(2, "teamKick:left"));
        receive(2_000_000, 2, m, false);
        assertEquals(0.75, plot.snapshot().get(0).y()[0], 1e-6);
        assertEquals(1, plot.snapshot().get(1).y()[0], "a bool plots as 0 or 1");
    }

    @Test
    void aPathThatDoesNotFitTheMessageIsNoValue() {
        Fumanoid.Status s = Fumanoid.Status.newBuilder().setBatteryPercent(5).build();
        assertEquals(5, NumericFields.value(s, "batteryPercent"));
        assertTrue(Double.isNaN(NumericFields.value(s, "robotPosition.x")), "absent message on the way");
        assertTrue(Double.isNaN(NumericFields.value(s, "robotName")));
        assertTrue(Double.isNaN(NumericFields.value(s, "batteryPercent.x")));
        assertTrue(Double.isNaN(NumericFields.value(s, "")));
    }
}
