package touchline.model;

import com.google.protobuf.ByteString;
import com.google.protobuf.Message;
import touchline.proto.Fumanoid;
import touchline.protocol.ros2.RosImage;
import touchline.protocol.ros2.RosMessage;

import java.util.Optional;

/**
 * A ROS 2 robot's message as the debug data a small robot would send, so the views that show
 * small robots' data show it unchanged, its topic as the option: {@code sensor_msgs/msg/Image}
 * and {@code CompressedImage} → an image ({@link RosImage}); {@code sensor_msgs/msg/JointState}
 * and {@code diagnostic_msgs/msg/DiagnosticArray} → a table ({@link RosTables}). Pure.
 */
public final class RosDebugData {

    /** One translated message: the data and the kind of view that shows it (a {@code DebugKind} value). */
    public record Data(Message data, int debugKind) { }

    private final RosImage images = new RosImage();
    private final RosTables tables = new RosTables();

    /** The data {@code m} on {@code topic} shows as, if any; an image that cannot be shown is none. */
    public Optional<Data> of(String topic, RosMessage m) {
        if (RosImage.isImage(m.typeName())) {
            return image(topic, images.frame(m));
        }
        return tables.table(topic, m).map(t -> new Data(t, Fumanoid.DebugKind.TABLE_VALUE));
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
            return Optional.empty();
        }
        return Optional.of(new Data(b.build(), Fumanoid.DebugKind.IMAGE_VALUE));
    }
}
