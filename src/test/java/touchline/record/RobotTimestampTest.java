package touchline.record;

import com.google.protobuf.DescriptorProtos.DescriptorProto;
import com.google.protobuf.DescriptorProtos.FieldDescriptorProto;
import com.google.protobuf.DescriptorProtos.FileDescriptorProto;
import com.google.protobuf.Descriptors.Descriptor;
import com.google.protobuf.Descriptors.FileDescriptor;
import com.google.protobuf.DynamicMessage;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import touchline.proto.Fumanoid;

import java.util.Arrays;
import java.util.HexFormat;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

class RobotTimestampTest {

    private static final long FALLBACK = -42;

    private static Fumanoid.Message status(long timestamp) {
        return Fumanoid.Message.newBuilder().setRobotID(3).setExtension(Fumanoid.status, Fumanoid.Status.newBuilder()
                .setTeamID(13).setRobotName("fu3").setTimestamp(timestamp).setBatteryPercent(80).build()).build();
    }

    private static long read(Fumanoid.Message m) {
        byte[] b = m.toByteArray();
        return RobotTimestamp.of(m).nanos(b, 0, b.length, FALLBACK);
    }

    @Test
    void readsTheTimestampOfTheCarriedExtensionFromTheBytes() {
        assertEquals(123_456_789L * 1_000_000L, read(status(123_456_789L)));
        assertEquals((1L << 40) * 1_000_000L, read(status(1L << 40)));
        // a timestamp after a repeated submessage field, in another extension
        Fumanoid.DebugPlot.Builder plot = Fumanoid.DebugPlot.newBuilder().setOption("p");
        for (int i = 0; i < 20; i++) {
            plot.addSamples(Fumanoid.PlotSample.newBuilder().setSeries("s" + i).setValue(i));
        }
        Fumanoid.Message m = Fumanoid.Message.newBuilder().setRobotID(1)
                .setExtension(Fumanoid.debugPlot, plot.setTimestamp(77).build()).build();
        assertEquals(77_000_000L, read(m));
    }

    @Test
    void fallsBackWhenTheMessageHasNoTimestampOrTheBytesAreCut() {
        Fumanoid.Message without = Fumanoid.Message.newBuilder().setRobotID(3)
                .setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTeamID(13).build()).build();
        byte[] b = without.toByteArray();
        assertEquals(FALLBACK, new RobotTimestamp(Fumanoid.status.getNumber(),
                Fumanoid.Status.getDescriptor().findFieldByName("timestamp")).nanos(b, 0, b.length, FALLBACK));
        byte[] full = status(5).toByteArray();
        RobotTimestamp where = RobotTimestamp.of(status(5));
        for (int cut = 0; cut < full.length; cut++) {
            byte[] part = Arrays.copyOf(full, cut);
            long t = where.nanos(part, 0, part.length, FALLBACK);
            // a cut before the timestamp's last byte never invents a value
            assertEquals(true, t == FALLBACK || t == 5_000_000L, "cut at " + cut + " gave " + t);
        }
        byte[] garbage = {(byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF,
                (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF};
        assertEquals(FALLBACK, where.nanos(garbage, 0, garbage.length, FALLBACK));
    }

    @Test
    @Timeout(value = 10, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD) // a guard: before the fix the walk never returned
    void aLengthNear2To63EndsTheWalk() {
        RobotTimestamp where = RobotTimestamp.of(status(5));
        // field 1 = 1, then field 2 with a length of 2^63 - 12 (a fuzzer found it; protobuf rejects it first)
        byte[] skipped = HexFormat.of().parseHex("080112f4ffffffffffffff7f");
        assertEquals(FALLBACK, where.nanos(skipped, 0, skipped.length, FALLBACK));
        // the same length on the extension itself
        byte[] extension = HexFormat.of().parseHex("0801ba01f4ffffffffffffff7f");
        assertEquals(FALLBACK, where.nanos(extension, 0, extension.length, FALLBACK));
    }

    @Test
    void readsWithinAnOffsetWindowOnly() {
        byte[] payload = status(9).toByteArray();
        byte[] framed = new byte[payload.length + 16];
        System.arraycopy(payload, 0, framed, 12, payload.length);
        assertEquals(9_000_000L, RobotTimestamp.of(status(9)).nanos(framed, 12, payload.length, FALLBACK));
    }

    @Test
    void zigZagAndFixedTimestampsOfTeamMessagesDecodeLikeProtobuf() throws Exception {
        Descriptor type = teamType();
        DynamicMessage sint = DynamicMessage.newBuilder(type).setField(type.findFieldByName("timestamp"), 1234L).build();
        // wrap as field 1500 of an outer message, as an extension of Message would be on the wire
        assertEquals(1234L * 1_000_000L, readWrapped(type, "timestamp", sint));
        DynamicMessage fixed = DynamicMessage.newBuilder(type).setField(type.findFieldByName("stamp"), 987654321L).build();
        assertEquals(987654321L * 1_000_000L, readWrapped(type, "stamp", fixed));
        assertNull(RobotTimestamp.of(Fumanoid.Message.newBuilder().setRobotID(1).build()));
    }

    private static long readWrapped(Descriptor type, String field, DynamicMessage inner) {
        byte[] body = inner.toByteArray();
        byte[] outer = new byte[body.length + 4];
        int at = 0;
        outer[at++] = 0x08; // robotID = 1
        outer[at++] = 0x01;
        outer[at++] = (byte) ((1500 << 3 | 2) & 0x7F | 0x80);
        outer[at++] = (byte) ((1500 << 3 | 2) >>> 7);
        byte[] all = new byte[at + 1 + body.length];
        System.arraycopy(outer, 0, all, 0, at);
        all[at++] = (byte) body.length;
        System.arraycopy(body, 0, all, at, body.length);
        return new RobotTimestamp(1500, type.findFieldByName(field)).nanos(all, 0, all.length, FALLBACK);
    }

    private static Descriptor teamType() throws Exception {
        FileDescriptorProto file = FileDescriptorProto.newBuilder().setName("team.proto").setPackage("team")
                .addMessageType(DescriptorProto.newBuilder().setName("Odometry")
                        .addField(FieldDescriptorProto.newBuilder().setName("x").setNumber(1)
                                .setType(FieldDescriptorProto.Type.TYPE_DOUBLE))
                        .addField(FieldDescriptorProto.newBuilder().setName("timestamp").setNumber(2)
                                .setType(FieldDescriptorProto.Type.TYPE_SINT64))
                        .addField(FieldDescriptorProto.newBuilder().setName("stamp").setNumber(3)
                                .setType(FieldDescriptorProto.Type.TYPE_FIXED64)))
                .build();
        return FileDescriptor.buildFrom(file, new FileDescriptor[0]).findMessageTypeByName("Odometry");
    }
}
