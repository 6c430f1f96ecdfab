package touchline.protocol.ros2;

/** A schema that does not parse, thrown inside the parser and turned into {@link DefinitionResult.Refused} at its edge. */
final class DefinitionException extends Exception {

    private final int line;

    DefinitionException(int line, String reason) {
        super(reason, null, false, false);
        this.line = line;
    }

    int line() {
        return line;
    }

    DefinitionResult.Refused refused() {
        return new DefinitionResult.Refused(line > 0 ? "line " + line + ": " + getMessage() : getMessage(), line);
    }
}
