package touchline.record.foxglove;

import com.google.protobuf.ByteString;
import touchline.proto.Fumanoid;
import touchline.proto.Nao;
import touchline.protocol.FrameCodec;
import touchline.protocol.MessageKinds;
import touchline.record.ChunkCompression;
import touchline.record.EnvelopeWriter;
import touchline.record.Recording;
import touchline.record.RecordingException;
import touchline.protocol.Framing;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Envelopes of every kind the standard schemas take, as a robot or the NAO camera would send them. */
public final class FoxgloveFixture {

    private FoxgloveFixture() {
    }

    public static Envelope in(long micros, int robot, String kind, Fumanoid.Message m) {
        return new Envelope(micros, Direction.IN, Channel.FUMANOID, new InetSocketAddress("127.0.0.1", 40000 + robot),
                robot, kind, m, new FrameCodec().encode(Framing.LENGTH_PREFIX, m.toByteArray()), null);
    }

    public static Envelope text(long micros, int robot, String option, String text) {
        return in(micros, robot, "debugText", Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.debugText,
                Fumanoid.DebugText.newBuilder().setOption(option).setText(text).build()).build());
    }

    public static Envelope image(long micros, int robot, Fumanoid.ImageFormat format, int w, int h, byte[] data) {
        return in(micros, robot, "debugImage", Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(
                Fumanoid.debugImage, Fumanoid.DebugImage.newBuilder().setOption("demo.image").setWidth(w).setHeight(h)
                        .setFormat(format.getNumber()).setData(ByteString.copyFrom(data)).build()).build());
    }

    public static Envelope regions(long micros, int robot, int[]... boxes) {
        Fumanoid.RegionGrowing.Builder r = Fumanoid.RegionGrowing.newBuilder().setOption("havimo.region")
                .setFrameWidth(160).setFrameHeight(120);
        for (int[] b : boxes) {
            r.addRegions(Fumanoid.Region.newBuilder().setColorClass(b[0]).setX1(b[1]).setY1(b[2]).setX2(b[3]).setY2(b[4]));
        }
        return in(micros, robot, "regionGrowing", Fumanoid.Message.newBuilder().setRobotID(robot)
                .setExtension(Fumanoid.regionGrowing, r.build()).build());
    }

    public static Envelope status(long micros, int robot, float x, float y, float theta) {
        return in(micros, robot, "status", Fumanoid.Message.newBuilder().setRobotID(robot).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setRobotName("striker").setBatteryPercent(80)
                        .setRobotPosition(Fumanoid.Position.newBuilder().setX(x).setY(y).setTheta(theta)).build()).build());
    }

    public static Envelope naoFrame(long micros, byte[] jpeg) {
        Nao.CamResponse r = Nao.CamResponse.newBuilder().setImageData(ByteString.copyFrom(jpeg)).build();
        return new Envelope(micros, Direction.IN, Channel.NAO_CAMERA, InetSocketAddress.createUnresolved("nao", 5556),
                Envelope.NO_ROBOT, "frame", r, r.toByteArray(), null);
    }

    /** Records {@code sent} as the console would ({@code dir/recording.mcap}), exports it for Foxglove; returns the export. */
    public static Path recordAndExport(Path dir, List<Envelope> sent) throws IOException {
        Path recording = dir.resolve("recording.mcap");
        try (EnvelopeWriter w = new EnvelopeWriter(recording, EnvelopeWriter.Options.defaults())) {
            for (Envelope e : sent) {
                w.write(e);
            }
        }
        Path export = dir.resolve("recording-foxglove.mcap");
        try (Recording r = Recording.open(recording); OutputStream out = Files.newOutputStream(export)) {
            new FoxgloveExport(new MessageKinds()).write(r, out, ChunkCompression.NONE);
        } catch (RecordingException e) {
            throw new IOException(e.getMessage(), e);
        }
        return export;
    }

    /** A real JPEG (a gradient), as a camera would send. */
    public static byte[] jpeg(int w, int h) throws IOException {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.setRGB(x, y, (x * 255 / w) << 16 | (y * 255 / h) << 8 | 0x40);
            }
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ImageIO.write(img, "jpeg", out);
        return out.toByteArray();
    }
}
