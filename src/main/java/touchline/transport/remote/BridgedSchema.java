package touchline.transport.remote;

/**
 * A bridged channel's own encoding and schema as its server advertised them ({@code cdr} with a
 * {@code ros2msg} definition, {@code json}, {@code protobuf}): what a recording keeps, so other
 * tools ({@code mcap_ros2}, Foxglove, Lichtblick) read the channel as the robot sent it.
 */
public record BridgedSchema(String messageEncoding, String schemaName, String schemaEncoding, byte[] schemaData) {

    /** Where a recorder finds a robot's channel's schema: by robot number and topic; null when none. */
    @FunctionalInterface
    public interface Source {
        Source NONE = (robotId, topic) -> null;

        BridgedSchema of(int robotId, String topic);
    }
}
