package touchline.protocol.ros2;

/**
 * One field of a {@link MessageType}: its name, its element type (a {@link Primitive} or the
 * full name of a message type, {@code pkg/msg/Type}), and its shape. {@code bound} is the
 * length of a fixed array or the maximum of a bounded sequence (0 otherwise);
 * {@code stringBound} the maximum of a bounded string ({@code string<=N}, 0 when unbounded).
 *
 * @param primitive the element's primitive type, or null when {@code typeName} names a message type
 * @param typeName  the element's message type, {@code pkg/msg/Type}, or null for a primitive
 */
public record Field(String name, Primitive primitive, String typeName, Shape shape, int bound, int stringBound) {

    /** How many elements a field holds. */
    public enum Shape {
        /** One value. */
        SINGLE,
        /** {@code T[N]}: exactly N, no length on the wire. */
        FIXED_ARRAY,
        /** {@code T[<=N]}: a length (uint32) then at most N. */
        BOUNDED_SEQUENCE,
        /** {@code T[]}: a length (uint32) then that many. */
        SEQUENCE
    }

    public boolean isArray() {
        return shape != Shape.SINGLE;
    }

    public boolean isMessage() {
        return primitive == null;
    }

    /** The type as a {@code .msg} file writes it, e.g. {@code float64[3]}, {@code geometry_msgs/msg/Pose}. */
    public String typeText() {
        String element = primitive == null ? typeName
                : primitive.word() + (stringBound > 0 ? "<=" + stringBound : "");
        return switch (shape) {
            case SINGLE -> element;
            case FIXED_ARRAY -> element + "[" + bound + "]";
            case BOUNDED_SEQUENCE -> element + "[<=" + bound + "]";
            case SEQUENCE -> element + "[]";
        };
    }
}
