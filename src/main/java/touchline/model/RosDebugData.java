package touchline.model;

import com.google.protobuf.ByteString;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.ros2.RosImage;
import touchline.protocol.ros2.RosMessage;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * A ROS 2 robot's message as the debug data a small robot would send, so the views that show
 * small robots' data show it unchanged, its topic as the option: {@code sensor_msgs/msg/Image}
 * and {@code CompressedImage} → an image ({@link RosImage}); {@code sensor_msgs/msg/JointState}
 * and {@code diagnostic_msgs/msg/DiagnosticArray} → a table ({@link RosTables});
 * {@code visualization_msgs/msg/MarkerArray} → a drawing on the field ({@link MarkerScene}: the
 * markers so far of that robot's topic, so this one keeps a scene per robot and topic, at most
 * {@link #MAX_SCENES}). Not thread-safe: one writer.
 */
public final class RosDebugData {

    /** One translated message: the data and the kind of view that shows it (a {@code DebugKind} value). */
    public record Data(Message data, int debugKind) { }

    public static final int MAX_SCENES = 256;

    private record SceneKey(int robotId, String topic) { }

    private final RosImage images = new RosImage();
    private final RosTables tables = new RosTables();
    private final Map<SceneKey, MarkerScene> scenes = new HashMap<>();

    /**
     * The data {@code m} on robot {@code robotId}'s {@code topic} shows as, if any; an image that cannot be
     * shown is a text with the reason, for the image view to say.
     */
    public Optional<Data> of(int robotId, String topic, RosMessage m) {
        if (RosImage.isImage(m.typeName())) {
            return image(topic, images.frame(m));
        }
        if (m.typeName().equals("visualization_msgs/msg/MarkerArray") || m.typeName().equals("visualization_msgs/msg/Marker")) {
            SceneKey key = new SceneKey(robotId, topic);
            MarkerScene scene = scenes.get(key);
            if (scene == null) {
                if (scenes.size() >= MAX_SCENES) {
                    return Optional.empty();
                }
                scene = new MarkerScene();
                scenes.put(key, scene);
            }
            scene.apply(m);
            return Optional.of(new Data(scene.drawing(topic), Fumanoid.DebugKind.FIELD_VALUE));
        }
        return tables.table(topic, m).map(t -> new Data(t, Fumanoid.DebugKind.TABLE_VALUE));
    }

    /** Forgets every scene (the stores start afresh). */
    public void forget() {
        scenes.clear();
    }

    private static Optional<Data> image(String topic, RosImage.Frame frame) {
        Fumanoid.DebugImage.Builder b = Fumanoid.DebugImage.newBuilder().setOption(topic);
        if (frame instanceof RosImage.Pixels p) {
            b.setWidth(p.width()).setHeight(p.height())
                    .setFormat((p.grey() ? Fumanoid.ImageFormat.GRAY8 : Fumanoid.ImageFormat.RGB888).getNumber())
                    .setData(ByteString.copyFrom(p.data()));
        } else if (frame instanceof RosImage.Compressed c) {
            b.setFormat((c.png() ? Fumanoid.ImageFormat.PNG : Fumanoid.ImageFormat.JPEG).getNumber())
                    .setData(ByteString.copyFrom(c.data()));
        } else {
            // shown in the image view in place of the frame, with the reason
            return Optional.of(new Data(Fumanoid.DebugText.newBuilder().setOption(topic)
                    .setText(((RosImage.Refused) frame).reason()).build(), Fumanoid.DebugKind.IMAGE_VALUE));
        }
        return Optional.of(new Data(b.build(), Fumanoid.DebugKind.IMAGE_VALUE));
    }
}
