package touchline.protocol.ros2;

/** The full names of ROS 2 message types: {@code pkg/msg/Type}, whatever form a schema wrote them in. */
final class TypeNames {

    private TypeNames() {
    }

    /**
     * {@code pkg/msg/Type} for {@code pkg/Type}, {@code pkg/msg/Type} or {@code pkg::msg::Type};
     * null when the name has another shape.
     */
    static String full(String name) {
        String n = name.trim().replace("::", "/");
        String[] parts = n.split("/", -1);
        for (String p : parts) {
            if (p.isEmpty()) {
                return null;
            }
        }
        return switch (parts.length) {
            case 2 -> parts[0] + "/msg/" + parts[1];
            case 3 -> n;
            default -> null;
        };
    }

    /** The package of a full name ({@code geometry_msgs} of {@code geometry_msgs/msg/Pose}). */
    static String packageOf(String fullName) {
        int slash = fullName.indexOf('/');
        return slash < 0 ? "" : fullName.substring(0, slash);
    }
}
