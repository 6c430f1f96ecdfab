package touchline.record.foxglove;

import com.google.protobuf.ByteString;
import com.google.protobuf.InvalidProtocolBufferException;
import com.google.protobuf.Timestamp;
import touchline.proto.Fumanoid;
import touchline.proto.Nao;
import touchline.proto.foxglove.Color;
import touchline.proto.foxglove.CompressedImage;
import touchline.proto.foxglove.CubePrimitive;
import touchline.proto.foxglove.FrameTransform;
import touchline.proto.foxglove.FrameTransforms;
import touchline.proto.foxglove.ImageAnnotations;
import touchline.proto.foxglove.Log;
import touchline.proto.foxglove.Point2;
import touchline.proto.foxglove.PointsAnnotation;
import touchline.proto.foxglove.Pose;
import touchline.proto.foxglove.Quaternion;
import touchline.proto.foxglove.RawImage;
import touchline.proto.foxglove.SceneEntity;
import touchline.proto.foxglove.SceneUpdate;
import touchline.proto.foxglove.SpherePrimitive;
import touchline.proto.foxglove.TextAnnotation;
import touchline.proto.foxglove.TextPrimitive;
import touchline.proto.foxglove.Vector3;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Touchline's envelopes as Foxglove standard messages, so Foxglove and Lichtblick show them in
 * their own panels without any Touchline code. What a robot sends maps as:
 * <ul>
 * <li>{@code debugText} → {@code foxglove.Log} on {@code /robot/N/log} (level INFO, name
 *     {@code robotN/option}, timestamp = the time the console received it);</li>
 * <li>{@code debugImage} → {@code foxglove.CompressedImage} (JPEG, PNG) or {@code foxglove.RawImage}
 *     (GRAY8 as mono8, RGB888 as rgb8) on {@code /robot/N/camera}, frame {@code robotN/option};</li>
 * <li>{@code regionGrowing} → {@code foxglove.ImageAnnotations} on {@code /robot/N/regions} (each
 *     region a closed LINE_LOOP rectangle in its colour class's colour, with its class as text) and,
 *     since the HaViMo2 sends no pixels, a dark PNG of the frame's size on {@code /robot/N/regions/frame}
 *     at the same timestamp and frame, for the Image panel to draw them on;</li>
 * <li>{@code status} with a position → {@code foxglove.FrameTransforms} on {@code /tf} (field → robotN)
 *     and a {@code foxglove.SceneUpdate} on {@code /field/scene} (a cube and the robot's name);</li>
 * <li>{@code fieldObjects} → {@code SceneUpdate} on {@code /field/scene} (a sphere per object, in
 *     the field frame); {@code relativePositions} → {@code SceneUpdate} on {@code /robot/N/relative}
 *     (in the robot's frame, which {@code /tf} places on the field);</li>
 * <li>the NAO camera's frames → {@code CompressedImage} on {@code /nao/camera/image}.</li>
 * </ul>
 * Field coordinates are millimetres on the wire and metres here. Plots, tables and grids have no
 * standard schema that fits (a Plot panel takes any numeric field of the raw channels). Only
 * what robots send is converted (not the console's own requests), never a malformed datagram.
 * A message whose content cannot be shown (an image format without a standard encoding, a
 * camera reply that does not parse) is counted in {@link #skipped()}. Safe to call from several
 * threads (the live server's publishers).
 */
public final class StandardMessages {

    /** The field's frame in the 3D panel; robots are {@code robotN} under it. */
    public static final String FIELD_FRAME = "field";
    /** How long a robot's or object's marker stays without a new message (it vanishes when the robot goes offline). */
    static final long LIFETIME_NANOS = 1_000_000_000L;
    private static final double MM = 0.001;

    private static final int[] CLASS_RGB = {0x404040, 0xFFA500, 0x228B22, 0xFFD700, 0x1E90FF, 0xFFFFFF, 0x00FFFF,
            0xFF00FF};
    private static final String[] CLASS_NAMES = {"unclassified", "ball", "field", "goal yellow", "goal blue", "white",
            "team cyan", "team magenta"};

    private final Canvas canvas = new Canvas();
    private final java.util.concurrent.atomic.AtomicLong skipped = new java.util.concurrent.atomic.AtomicLong();

    /** The standard messages {@code e} maps to; empty when nothing fits. */
    public List<StandardMessage> convert(Envelope e) {
        if (e.direction() != Direction.IN || e.isMalformed()) {
            return List.of();
        }
        long nanos = e.timeMicros() * 1000;
        if (e.channel() == Channel.NAO_CAMERA) {
            return e.kind().equals("frame") ? naoFrame(e, nanos) : List.of();
        }
        if (e.channel() != Channel.FUMANOID && e.channel() != Channel.RELIABLE_STREAM) {
            return List.of();
        }
        String robot = robotName(e.robotId());
        String base = "/" + topicRobot(e.robotId());
        switch (e.kind()) {
            case "debugText" -> {
                Fumanoid.DebugText t = e.extension(Fumanoid.debugText);
                return t == null ? List.of() : List.of(log(base, robot, nanos, t));
            }
            case "debugImage" -> {
                Fumanoid.DebugImage i = e.extension(Fumanoid.debugImage);
                return i == null ? List.of() : image(base, robot, nanos, i);
            }
            case "regionGrowing" -> {
                Fumanoid.RegionGrowing r = e.extension(Fumanoid.regionGrowing);
                return r == null ? List.of() : regions(base, robot, nanos, r);
            }
            case "status" -> {
                Fumanoid.Status s = e.extension(Fumanoid.status);
                return s == null || !s.hasRobotPosition() ? List.of() : robotPose(robot, nanos, s);
            }
            case "fieldObjects" -> {
                Fumanoid.FieldObjects f = e.extension(Fumanoid.fieldObjects);
                return f == null ? List.of()
                        : List.of(objects("/field/scene", FIELD_FRAME, robot, nanos, f.getObjectsList()));
            }
            case "relativePositions" -> {
                Fumanoid.RelativePositions r = e.extension(Fumanoid.relativePositions);
                return r == null ? List.of()
                        : List.of(objects(base + "/relative", robot, robot, nanos,
                                r.getObjectsList()));
            }
            default -> {
                return List.of();
            }
        }
    }

    /** Messages whose content had no standard form (an image format, an unreadable camera reply). */
    public long skipped() {
        return skipped.get();
    }

    /** {@code robot3}, or {@code robot-unknown} when the datagram did not say. */
    static String robotName(int robotId) {
        return "robot" + (robotId == Envelope.NO_ROBOT ? "-unknown" : Integer.toString(robotId));
    }

    private static String topicRobot(int robotId) {
        return "robot/" + (robotId == Envelope.NO_ROBOT ? "unknown" : Integer.toString(robotId));
    }

    static Timestamp timestamp(long nanos) {
        return Timestamp.newBuilder().setSeconds(Math.floorDiv(nanos, 1_000_000_000L))
                .setNanos((int) Math.floorMod(nanos, 1_000_000_000L)).build();
    }

    private static StandardMessage log(String base, String robot, long nanos, Fumanoid.DebugText t) {
        Log log = Log.newBuilder().setTimestamp(timestamp(nanos)).setLevel(Log.Level.INFO).setMessage(t.getText())
                .setName(robot + "/" + t.getOption()).build();
        return new StandardMessage(base + "/log", nanos, log);
    }

    private List<StandardMessage> image(String base, String robot, long nanos, Fumanoid.DebugImage i) {
        String topic = base + "/camera";
        String frame = robot + "/" + i.getOption();
        Timestamp t = timestamp(nanos);
        ByteString data = i.getData();
        int w = i.getWidth();
        int h = i.getHeight();
        switch (i.getFormat()) {
            case Fumanoid.ImageFormat.JPEG_VALUE, Fumanoid.ImageFormat.PNG_VALUE -> {
                String format = i.getFormat() == Fumanoid.ImageFormat.JPEG_VALUE ? "jpeg" : "png";
                return List.of(new StandardMessage(topic, nanos, CompressedImage.newBuilder().setTimestamp(t)
                        .setFrameId(frame).setFormat(format).setData(data).build()));
            }
            case Fumanoid.ImageFormat.GRAY8_VALUE, Fumanoid.ImageFormat.RGB888_VALUE -> {
                int channels = i.getFormat() == Fumanoid.ImageFormat.GRAY8_VALUE ? 1 : 3;
                if (w <= 0 || h <= 0 || (long) w * h * channels != data.size()) {
                    skipped.incrementAndGet(); // the viewer would draw garbage or fail
                    return List.of();
                }
                return List.of(new StandardMessage(topic, nanos, RawImage.newBuilder().setTimestamp(t).setFrameId(frame)
                        .setWidth(w).setHeight(h).setEncoding(channels == 1 ? "mono8" : "rgb8").setStep(w * channels)
                        .setData(data).build()));
            }
            default -> {
                skipped.incrementAndGet(); // COLOR_CLASSES and unknown formats have no standard encoding
                return List.of();
            }
        }
    }

    private List<StandardMessage> regions(String base, String robot, long nanos, Fumanoid.RegionGrowing r) {
        String topic = base + "/regions";
        String frame = robot + "/" + r.getOption();
        Timestamp t = timestamp(nanos);
        ImageAnnotations.Builder a = ImageAnnotations.newBuilder();
        for (Fumanoid.Region region : r.getRegionsList()) {
            Color c = classColor(region.getColorClass());
            a.addPoints(PointsAnnotation.newBuilder().setTimestamp(t).setType(PointsAnnotation.Type.LINE_LOOP)
                    .addPoints(point(region.getX1(), region.getY1())).addPoints(point(region.getX2(), region.getY1()))
                    .addPoints(point(region.getX2(), region.getY2())).addPoints(point(region.getX1(), region.getY2()))
                    .setOutlineColor(c).setThickness(1));
            a.addTexts(TextAnnotation.newBuilder().setTimestamp(t).setPosition(point(region.getX1(), region.getY1() - 1))
                    .setText(className(region.getColorClass())).setFontSize(8).setTextColor(c)
                    .setBackgroundColor(Color.newBuilder().setA(0.5)));
        }
        List<StandardMessage> out = new ArrayList<>(2);
        ByteString png = canvas.png((int) r.getFrameWidth(), (int) r.getFrameHeight());
        if (png != null) {
            out.add(new StandardMessage(topic + "/frame", nanos, CompressedImage.newBuilder().setTimestamp(t)
                    .setFrameId(frame).setFormat("png").setData(png).build()));
        }
        out.add(new StandardMessage(topic, nanos, a.build()));
        return out;
    }

    private static Point2 point(int x, int y) {
        return Point2.newBuilder().setX(x).setY(y).build();
    }

    private static Color classColor(int colorClass) {
        int rgb = colorClass >= 0 && colorClass < CLASS_RGB.length ? CLASS_RGB[colorClass] : 0x808080;
        return Color.newBuilder().setR(((rgb >> 16) & 0xFF) / 255.0).setG(((rgb >> 8) & 0xFF) / 255.0)
                .setB((rgb & 0xFF) / 255.0).setA(1).build();
    }

    private static String className(int colorClass) {
        return colorClass >= 0 && colorClass < CLASS_NAMES.length ? CLASS_NAMES[colorClass] : "class " + colorClass;
    }

    private static List<StandardMessage> robotPose(String robot, long nanos, Fumanoid.Status s) {
        Fumanoid.Position p = s.getRobotPosition();
        Timestamp t = timestamp(nanos);
        Quaternion yaw = yaw(p.getTheta());
        FrameTransforms tf = FrameTransforms.newBuilder().addTransforms(FrameTransform.newBuilder().setTimestamp(t)
                .setParentFrameId(FIELD_FRAME).setChildFrameId(robot)
                .setTranslation(Vector3.newBuilder().setX(p.getX() * MM).setY(p.getY() * MM))
                .setRotation(yaw)).build();
        String label = s.hasRobotName() && !s.getRobotName().isEmpty() ? s.getRobotName() + " (" + robot + ")" : robot;
        SceneEntity entity = SceneEntity.newBuilder().setTimestamp(t).setFrameId(FIELD_FRAME).setId(robot)
                .setLifetime(com.google.protobuf.Duration.newBuilder().setSeconds(LIFETIME_NANOS / 1_000_000_000L))
                .addCubes(CubePrimitive.newBuilder()
                        .setPose(Pose.newBuilder().setPosition(Vector3.newBuilder().setX(p.getX() * MM)
                                .setY(p.getY() * MM).setZ(0.2)).setOrientation(yaw))
                        .setSize(Vector3.newBuilder().setX(0.2).setY(0.15).setZ(0.4))
                        .setColor(Color.newBuilder().setR(0.12).setG(0.56).setB(1).setA(0.9)))
                .addTexts(TextPrimitive.newBuilder()
                        .setPose(Pose.newBuilder().setPosition(Vector3.newBuilder().setX(p.getX() * MM)
                                .setY(p.getY() * MM).setZ(0.55)).setOrientation(Quaternion.newBuilder().setW(1)))
                        .setBillboard(true).setFontSize(14).setScaleInvariant(true).setText(label)
                        .setColor(Color.newBuilder().setR(1).setG(1).setB(1).setA(1)))
                .build();
        return List.of(new StandardMessage("/tf", nanos, tf),
                new StandardMessage("/field/scene", nanos, SceneUpdate.newBuilder().addEntities(entity).build()));
    }

    private static StandardMessage objects(String topic, String frame, String robot, long nanos,
                                           List<Fumanoid.RelativeObject> objects) {
        Timestamp t = timestamp(nanos);
        SceneUpdate.Builder u = SceneUpdate.newBuilder();
        int n = 0;
        for (Fumanoid.RelativeObject o : objects) {
            String label = o.getLabel().isEmpty() ? "object " + n : o.getLabel();
            Vector3 at = Vector3.newBuilder().setX(o.getX() * MM).setY(o.getY() * MM).setZ(0.05).build();
            u.addEntities(SceneEntity.newBuilder().setTimestamp(t).setFrameId(frame)
                    .setId(robot + "/" + label.toLowerCase(Locale.ROOT) + "#" + n++)
                    .setLifetime(com.google.protobuf.Duration.newBuilder().setSeconds(LIFETIME_NANOS / 1_000_000_000L))
                    .addSpheres(SpherePrimitive.newBuilder().setPose(Pose.newBuilder().setPosition(at)
                                    .setOrientation(Quaternion.newBuilder().setW(1)))
                            .setSize(Vector3.newBuilder().setX(0.1).setY(0.1).setZ(0.1))
                            .setColor(classColor(o.hasColorClass() ? o.getColorClass() : 1)))
                    .addTexts(TextPrimitive.newBuilder().setPose(Pose.newBuilder()
                                    .setPosition(Vector3.newBuilder().setX(at.getX()).setY(at.getY()).setZ(0.2))
                                    .setOrientation(Quaternion.newBuilder().setW(1)))
                            .setBillboard(true).setFontSize(12).setScaleInvariant(true).setText(label)
                            .setColor(Color.newBuilder().setR(1).setG(1).setB(1).setA(1))));
        }
        return new StandardMessage(topic, nanos, u.build());
    }

    private static Quaternion yaw(double theta) {
        return Quaternion.newBuilder().setZ(Math.sin(theta / 2)).setW(Math.cos(theta / 2)).build();
    }

    private List<StandardMessage> naoFrame(Envelope e, long nanos) {
        Nao.CamResponse r;
        if (e.message() instanceof Nao.CamResponse live) {
            r = live;
        } else {
            try {
                r = Nao.CamResponse.parseFrom(e.raw()); // a recording keeps the reply's bytes
            } catch (InvalidProtocolBufferException x) {
                skipped.incrementAndGet();
                return List.of();
            }
        }
        ByteString jpeg = r.getImageData();
        String format = format(jpeg);
        if (format == null) {
            skipped.incrementAndGet();
            return List.of();
        }
        return List.of(new StandardMessage("/nao/camera/image", nanos, CompressedImage.newBuilder()
                .setTimestamp(timestamp(nanos)).setFrameId("nao/camera").setFormat(format).setData(jpeg).build()));
    }

    /** "jpeg" or "png" by the data's magic bytes; null for anything else. */
    private static String format(ByteString data) {
        if (data.size() > 3 && (data.byteAt(0) & 0xFF) == 0xFF && (data.byteAt(1) & 0xFF) == 0xD8) {
            return "jpeg";
        }
        if (data.size() > 8 && (data.byteAt(0) & 0xFF) == 0x89 && data.byteAt(1) == 'P' && data.byteAt(2) == 'N'
                && data.byteAt(3) == 'G') {
            return "png";
        }
        return null;
    }
}
