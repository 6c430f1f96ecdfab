package touchline.protocol.ros2;

/** The outcome of parsing a schema: a definition, or why not (naming the line). */
public sealed interface DefinitionResult {

    record Parsed(MessageDefinition definition) implements DefinitionResult { }

    /**
     * The schema does not parse. {@code line} is 1-based within the schema text (0 when the
     * problem is not on one line, such as a type no section defines); {@code reason} is a
     * sentence for the user that already names the line.
     */
    record Refused(String reason, int line) implements DefinitionResult { }
}
