package touchline.protocol.ros2;

import java.util.List;

/**
 * One message type of a definition ({@code geometry_msgs/msg/Pose}): its fields in wire order.
 * Constants are parsed and kept for the text, but are not on the wire. A type without fields
 * is one {@code uint8} on the wire (ROS 2 adds {@code structure_needs_at_least_one_member}).
 */
public record MessageType(String name, List<Field> fields, List<Constant> constants) {

    /** A constant of the type ({@code uint8 DEBUG=10}): its primitive, name and value as written. */
    public record Constant(Primitive primitive, String name, String value) { }

    public MessageType {
        fields = List.copyOf(fields);
        constants = List.copyOf(constants);
    }

    /** The field names in order: the names of a decoded {@link RosMessage} of this type (shared, not copied). */
    public String[] fieldNames() {
        return fields.stream().map(Field::name).toArray(String[]::new);
    }
}
