package touchline.protocol.ros2;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The {@code ros2msg} form: the root type's {@code .msg} text, then for each dependency a line
 * of {@code =} and a line {@code MSG: pkg/Type} followed by its text. Comments ({@code #}),
 * default values ({@code int32 x 5}) and constants ({@code uint8 DEBUG=10}) are read past;
 * {@code Header} means {@code std_msgs/msg/Header}, a bare type name one of the section's own
 * package.
 */
final class MsgParser {

    private static final Pattern SEPARATOR = Pattern.compile("^={3,}\\s*$");
    private static final Pattern TYPE = Pattern.compile(
            "([A-Za-z][A-Za-z0-9_]*(?:/[A-Za-z][A-Za-z0-9_]*){0,2})(?:<=([0-9]+))?(?:\\[(<=)?([0-9]*)\\])?");
    private static final Pattern NAME = Pattern.compile("([A-Za-z][A-Za-z0-9_]*)\\s*(=)?(.*)");

    /** Every section's type, by full name, in the order of the text (the root first). */
    Map<String, MessageType> parse(String rootName, String text) throws DefinitionException {
        Map<String, MessageType> types = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        String current = rootName;
        int start = 0;
        boolean expectName = false;
        List<Field> fields = new ArrayList<>();
        List<MessageType.Constant> constants = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            int lineNo = i + 1;
            String line = lines[i].strip();
            if (SEPARATOR.matcher(line).matches()) {
                add(types, current, fields, constants, start);
                fields = new ArrayList<>();
                constants = new ArrayList<>();
                current = null;
                expectName = true;
                continue;
            }
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (expectName) {
                if (!line.startsWith("MSG:")) {
                    throw new DefinitionException(lineNo, "after a line of '=' a dependency starts with 'MSG: pkg/Type', not '"
                            + cut(line) + "'");
                }
                current = TypeNames.full(line.substring(4));
                if (current == null) {
                    throw new DefinitionException(lineNo, "'" + cut(line.substring(4).strip())
                            + "' is not a message type name (pkg/Type or pkg/msg/Type)");
                }
                start = lineNo;
                expectName = false;
                continue;
            }
            fieldOrConstant(line, lineNo, TypeNames.packageOf(current), fields, constants);
        }
        if (expectName) {
            throw new DefinitionException(lines.length, "the schema ends after a line of '=' without 'MSG: pkg/Type'");
        }
        add(types, current, fields, constants, start);
        return types;
    }

    private static void add(Map<String, MessageType> types, String name, List<Field> fields,
                            List<MessageType.Constant> constants, int line) throws DefinitionException {
        if (types.containsKey(name)) {
            MessageType earlier = types.get(name);
            if (!earlier.fields().equals(fields)) {
                throw new DefinitionException(line, "the schema defines " + name + " twice, differently");
            }
            return;
        }
        types.put(name, new MessageType(name, fields, constants));
    }

    private static void fieldOrConstant(String line, int lineNo, String pkg, List<Field> fields,
                                        List<MessageType.Constant> constants) throws DefinitionException {
        int space = indexOfSpace(line);
        if (space < 0) {
            throw new DefinitionException(lineNo, "'" + cut(line) + "' is not a field (type name) or a constant (type NAME=value)");
        }
        String typeText = line.substring(0, space);
        Matcher t = TYPE.matcher(typeText);
        if (!t.matches()) {
            throw new DefinitionException(lineNo, "'" + cut(typeText) + "' is not a field type");
        }
        Matcher n = NAME.matcher(line.substring(space).strip());
        if (!n.matches()) {
            throw new DefinitionException(lineNo, "'" + cut(line.substring(space).strip()) + "' is not a field name");
        }
        String base = t.group(1);
        Primitive primitive = Primitive.ofWord(base);
        int stringBound = t.group(2) == null ? 0 : number(t.group(2), lineNo);
        if (stringBound > 0 && primitive != Primitive.STRING && primitive != Primitive.WSTRING) {
            throw new DefinitionException(lineNo, "only strings have a bound like '<=N', not " + base);
        }
        if (n.group(2) != null) {
            if (primitive == null || t.group(4) != null || t.group(3) != null || typeText.endsWith("]")) {
                throw new DefinitionException(lineNo, "a constant is of a single primitive type, not " + typeText);
            }
            String value = n.group(3).strip();
            if (primitive != Primitive.STRING && primitive != Primitive.WSTRING) {
                int hash = value.indexOf('#');
                value = (hash < 0 ? value : value.substring(0, hash)).strip();
            }
            if (value.isEmpty()) {
                throw new DefinitionException(lineNo, "the constant " + n.group(1) + " has no value");
            }
            constants.add(new MessageType.Constant(primitive, n.group(1), value));
            return;
        }
        Field.Shape shape = Field.Shape.SINGLE;
        int bound = 0;
        if (typeText.endsWith("]")) {
            if (t.group(3) != null) {
                if (t.group(4).isEmpty()) {
                    throw new DefinitionException(lineNo, "'" + typeText + "': a bounded sequence needs its bound, T[<=N]");
                }
                shape = Field.Shape.BOUNDED_SEQUENCE;
                bound = number(t.group(4), lineNo);
            } else if (t.group(4).isEmpty()) {
                shape = Field.Shape.SEQUENCE;
            } else {
                shape = Field.Shape.FIXED_ARRAY;
                bound = number(t.group(4), lineNo);
            }
        }
        String typeName = null;
        if (primitive == null) {
            typeName = resolve(base, pkg);
            if (typeName == null) {
                throw new DefinitionException(lineNo, "'" + base + "' is not a type name");
            }
        }
        fields.add(new Field(n.group(1), primitive, typeName, shape, bound, stringBound));
    }

    private static String resolve(String base, String pkg) {
        if (base.indexOf('/') >= 0) {
            return TypeNames.full(base);
        }
        if (base.equals("Header")) {
            return "std_msgs/msg/Header";
        }
        return pkg.isEmpty() ? null : pkg + "/msg/" + base;
    }

    private static int indexOfSpace(String line) {
        for (int i = 0; i < line.length(); i++) {
            if (Character.isWhitespace(line.charAt(i))) {
                return i;
            }
        }
        return -1;
    }

    static int number(String digits, int lineNo) throws DefinitionException {
        try {
            return Integer.parseInt(digits);
        } catch (NumberFormatException e) {
            throw new DefinitionException(lineNo, digits + " is too large a bound");
        }
    }

    static String cut(String s) {
        return s.length() > 60 ? s.substring(0, 60) + "…" : s;
    }
}
