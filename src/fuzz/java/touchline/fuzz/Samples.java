package touchline.fuzz;

import com.google.protobuf.ByteString;
import com.google.protobuf.UnknownFieldSet;
import touchline.proto.Fumanoid;
import touchline.proto.Nao;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** Well-formed inputs the targets start from: messages of every kind, and the golden files. */
final class Samples {

    /** One FUmanoids message of each extension we know, as payload bytes. */
    List<byte[]> messages() {
        List<Fumanoid.Message> all = new ArrayList<>();
        all.add(message().setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTimestamp(123456)
                .setTeamID(13).setTimeOnline(60).setRobotPosition(Fumanoid.Position.newBuilder().setX(1).setY(2).setTheta(0.5f))
                .setRobotPositionBelief(0.9).setActiveAgent("striker").setRobotName("fu3").setBatteryPercent(80)
                .setGameState("PLAYING").build()).build());
        all.add(message().setExtension(Fumanoid.debugOptionList, Fumanoid.DebugOptionList.newBuilder()
                .addOptions(Fumanoid.DebugOption.newBuilder().setName("vision.ball").setKind(2).setEnabled(true))
                .addOptions(Fumanoid.DebugOption.newBuilder().setName("text").setDescription("d")).build()).build());
        all.add(message().setExtension(Fumanoid.debugText, Fumanoid.DebugText.newBuilder().setOption("t")
                .setText("hello\nworld").setTimestamp(5).build()).build());
        all.add(message().setExtension(Fumanoid.debugPlot, Fumanoid.DebugPlot.newBuilder().setOption("p").setTimestamp(7)
                .addSamples(Fumanoid.PlotSample.newBuilder().setSeries("a").setValue(1.5)).build()).build());
        all.add(message().setExtension(Fumanoid.debugTable, Fumanoid.DebugTable.newBuilder().setOption("tab")
                .addHeader("h").addRows(Fumanoid.TableRow.newBuilder().addCells("c")).build()).build());
        all.add(message().setExtension(Fumanoid.regionGrowing, Fumanoid.RegionGrowing.newBuilder().setOption("r")
                .setFrameWidth(160).setFrameHeight(120).addRegions(Fumanoid.Region.newBuilder().setColorClass(1)
                        .setX1(1).setY1(2).setX2(30).setY2(40).setPixels(99)).build()).build());
        all.add(message().setExtension(Fumanoid.grid, Fumanoid.Grid.newBuilder().setOption("g").setColumns(2).setRows(2)
                .setCells(ByteString.copyFrom(new byte[]{0, 1, 2, 3})).build()).build());
        all.add(message().setExtension(Fumanoid.relativePositions, Fumanoid.RelativePositions.newBuilder().setOption("rel")
                .addObjects(Fumanoid.RelativeObject.newBuilder().setLabel("ball").setX(100).setY(-20)).build()).build());
        all.add(message().setExtension(Fumanoid.fieldObjects, Fumanoid.FieldObjects.newBuilder().setOption("f")
                .addObjects(Fumanoid.RelativeObject.newBuilder().setLabel("goal").setColorClass(3)).build()).build());
        all.add(message().setExtension(Fumanoid.debugImage, Fumanoid.DebugImage.newBuilder().setOption("img").setWidth(2)
                .setHeight(1).setFormat(0).setData(ByteString.copyFrom(new byte[]{10, 20})).build()).build());
        all.add(message().setExtension(Fumanoid.debugOptionRequest, Fumanoid.DebugOptionRequest.newBuilder()
                .setName("x").setEnable(true).build()).build());
        List<byte[]> bytes = new ArrayList<>();
        all.forEach(m -> bytes.add(m.toByteArray()));
        // a team's own extension no registered type knows: nested unknown fields
        bytes.add(new byte[]{0x08, 0x04, (byte) 0x92, 0x41, 0x06, 0x08, 0x07, 0x12, 0x02, 'o', 'k'});
        // unknown fields nested inside a known message, a few levels deep: mutations make them deeper
        bytes.add(message().setExtension(Fumanoid.status, Fumanoid.Status.newBuilder().setTimestamp(1)
                .setUnknownFields(nestedUnknown(12)).build()).build().toByteArray());
        return bytes;
    }

    /** Field 100 holding field 1 inside field 1 ... {@code depth} times, then two varints. */
    static UnknownFieldSet nestedUnknown(int depth) {
        return nestedUnknown(depth, ByteString.copyFrom(new byte[]{0x08, 0x01, 0x10, 0x02}));
    }

    /**
     * Field 100 holding field 1 inside field 1 ... {@code depth} times, then {@code inner}.
     * Mutating bytes rarely makes nesting deeper (every level's length must agree), so targets
     * that render also feed each input this way, {@code depth} read from the input itself.
     */
    static UnknownFieldSet nestedUnknown(int depth, ByteString inner) {
        for (int i = 0; i < depth; i++) {
            inner = UnknownFieldSet.newBuilder().addField(1, UnknownFieldSet.Field.newBuilder()
                    .addLengthDelimited(inner).build()).build().toByteString();
        }
        return UnknownFieldSet.newBuilder().addField(100, UnknownFieldSet.Field.newBuilder()
                .addLengthDelimited(inner).build()).build();
    }

    private static Fumanoid.Message.Builder message() {
        return Fumanoid.Message.newBuilder().setRobotID(3);
    }

    /** NAO replies, with return values of every MixedValue kind. */
    List<byte[]> naoReplies() {
        Nao.MixedValue list = Nao.MixedValue.newBuilder()
                .addArray(Nao.MixedValue.newBuilder().setString("HeadYaw"))
                .addArray(Nao.MixedValue.newBuilder().setInt(42))
                .addArray(Nao.MixedValue.newBuilder().setFloat(0.5f))
                .addArray(Nao.MixedValue.newBuilder().setBool(true))
                .addArray(Nao.MixedValue.newBuilder().setBinary(ByteString.copyFrom(new byte[]{1, 2, 3})))
                .addArray(Nao.MixedValue.newBuilder().addArray(Nao.MixedValue.newBuilder().setFloat(1)))
                .build();
        Nao.MixedValue.Builder deep = Nao.MixedValue.newBuilder().setUnknownFields(nestedUnknown(12));
        for (int i = 0; i < 12; i++) {
            deep = Nao.MixedValue.newBuilder().addArray(deep);
        }
        return List.of(Nao.HAWActorRPCResponse.newBuilder().setReturnval(list).build().toByteArray(),
                Nao.HAWActorRPCResponse.newBuilder().setReturnval(deep).build().toByteArray(),
                Nao.HAWActorRPCResponse.newBuilder().setError("no such method").build().toByteArray(),
                Nao.HAWActorRPCResponse.newBuilder().setReturnval(Nao.MixedValue.getDefaultInstance()).build().toByteArray());
    }

    /** Every file under {@code src/test/resources/golden/<dir>}, or none when run elsewhere. */
    List<byte[]> golden(String dir) {
        Path root = Path.of("src/test/resources/golden", dir);
        if (!Files.isDirectory(root)) {
            return List.of();
        }
        try (Stream<Path> files = Files.walk(root)) {
            List<byte[]> out = new ArrayList<>();
            for (Path p : files.filter(Files::isRegularFile).sorted().toList()) {
                out.add(Files.readAllBytes(p));
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
