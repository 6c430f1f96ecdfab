package touchline.transport.remote;

/**
 * A bridged channel's own encoding and schema as its server advertised them ({@code cdr} with a
 * {@code ros2msg} definition, {@code json}, {@code protobuf}): what a recording keeps, so other
 * tools ({@code mcap_ros2}, Foxglove, Lichtblick) read the channel as the robot sent it.
 */
public record BridgedSchema(String messageEncoding, String schemaName, String schemaEncoding, byte[] schemaData) {

    /** Whether the schema is a ROS 2 definition ({@code ros2msg} or {@code ros2idl}) a CDR message is written by. */
    public boolean isRos2() {
        return schemaEncoding.equals("ros2msg") || schemaEncoding.equals("ros2idl");
    }

    /** Where a recorder finds a robot's channel's schema: by robot number and topic; null when none. */
    @FunctionalInterface
    public interface Source {
        Source NONE = (robotId, topic) -> null;

        BridgedSchema of(int robotId, String topic);
    }
}
