package touchline.protocol.ros2;

/**
 * Parses ROS 2 schemas as MCAP files and Foxglove servers carry them: {@code ros2msg} (the
 * root type's {@code .msg} text, then each dependency after a line of {@code =} and
 * {@code MSG: pkg/Type}) and {@code ros2idl} (the IDL rosidl and the bridges emit, sections
 * separated the same way with {@code IDL: pkg/msg/Type}). Pure; never throws on bad text.
 */
public final class DefinitionParser {

    /** Parses {@code text}, the schema of {@code rootName} ({@code pkg/msg/Type} or {@code pkg/Type}) in {@code encoding}. */
    public DefinitionResult parse(String rootName, String encoding, String text) {
        return new DefinitionResult.Refused("not implemented yet", 0);
    }
}
