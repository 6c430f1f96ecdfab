package touchline.protocol.ros2;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Parses ROS 2 schemas as MCAP files and Foxglove servers carry them: {@code ros2msg} (the
 * root type's {@code .msg} text, then each dependency after a line of {@code =} and
 * {@code MSG: pkg/Type}) and {@code ros2idl} (the IDL rosidl and the bridges emit, sections
 * separated the same way with {@code IDL: pkg/msg/Type}). {@code builtin_interfaces/msg/Time}
 * and {@code Duration} are known without a section. A definition is handed out only when every
 * type it names is defined, no type contains itself (but through a sequence), types nest at
 * most {@link #MAX_NESTING} deep and every type takes at least one byte on the wire. Pure;
 * never throws on bad text.
 */
public final class DefinitionParser {

    /** How deep types may nest in a definition; real ones nest a handful of levels. */
    public static final int MAX_NESTING = 64;

    private static final Map<String, MessageType> BUILT_IN = Map.of(
            "builtin_interfaces/msg/Time", timeLike("builtin_interfaces/msg/Time"),
            "builtin_interfaces/msg/Duration", timeLike("builtin_interfaces/msg/Duration"));

    private static MessageType timeLike(String name) {
        return new MessageType(name, List.of(new Field("sec", Primitive.INT32, null, Field.Shape.SINGLE, 0, 0),
                new Field("nanosec", Primitive.UINT32, null, Field.Shape.SINGLE, 0, 0)), List.of());
    }

    /** Parses {@code text}, the schema of {@code rootName} ({@code pkg/msg/Type} or {@code pkg/Type}) in {@code encoding}. */
    public DefinitionResult parse(String rootName, String encoding, String text) {
        String root = TypeNames.full(rootName);
        if (root == null) {
            return new DefinitionResult.Refused("'" + MsgParser.cut(rootName) + "' is not a message type name"
                    + " (pkg/msg/Type)", 0);
        }
        try {
            Map<String, MessageType> types = switch (encoding) {
                case "ros2msg" -> new MsgParser().parse(root, text);
                case "ros2idl" -> new IdlParser(BUILT_IN.keySet()).parse(text);
                default -> throw new DefinitionException(0, "schema encoding '" + MsgParser.cut(encoding)
                        + "' is not ros2msg or ros2idl");
            };
            Map<String, MessageType> all = new LinkedHashMap<>(types);
            BUILT_IN.forEach(all::putIfAbsent);
            if (!all.containsKey(root)) {
                throw new DefinitionException(0, "the schema does not define its own type " + root);
            }
            check(root, all);
            return new DefinitionResult.Parsed(new MessageDefinition(root, all));
        } catch (DefinitionException e) {
            return e.refused();
        }
    }

    /** Every type named is defined; none contains itself but through a sequence; nesting is bounded. */
    private static void check(String root, Map<String, MessageType> types) throws DefinitionException {
        for (MessageType t : types.values()) {
            for (Field f : t.fields()) {
                if (f.isMessage() && !types.containsKey(f.typeName())) {
                    throw new DefinitionException(0, t.name() + "." + f.name() + " is of type " + f.typeName()
                            + ", which the schema does not define (a section 'MSG: "
                            + f.typeName().replace("/msg/", "/") + "' is missing)");
                }
            }
        }
        Map<String, Long> minSizes = new HashMap<>();
        for (String name : types.keySet()) {
            minSize(name, types, minSizes, new java.util.LinkedHashSet<>());
        }
        depth(root, types, 0, new HashMap<>());
    }

    /**
     * The fewest bytes a message of {@code name} takes (saturating at Long.MAX_VALUE); throws
     * on a type that contains itself without a sequence between, which no bytes can hold.
     */
    private static long minSize(String name, Map<String, MessageType> types, Map<String, Long> known,
                                java.util.LinkedHashSet<String> path) throws DefinitionException {
        Long k = known.get(name);
        if (k != null) {
            return k;
        }
        if (!path.add(name)) {
            throw new DefinitionException(0, "type " + name + " contains itself (" + String.join(" → ", path) + " → "
                    + name + ")");
        }
        if (path.size() > MAX_NESTING) {
            throw new DefinitionException(0, "types nest deeper than " + MAX_NESTING + " levels (" + name + ")");
        }
        MessageType t = types.get(name);
        long size = t.fields().isEmpty() ? 1 : 0;
        for (Field f : t.fields()) {
            boolean inline = f.shape() == Field.Shape.SINGLE || f.shape() == Field.Shape.FIXED_ARRAY;
            // a sequence is its count on the wire (its elements may be none): no recursion through it
            long element = !inline ? 4 : f.isMessage() ? minSize(f.typeName(), types, known, path)
                    : f.primitive().numeric() ? f.primitive().size() : 4;
            long fieldSize = f.shape() == Field.Shape.FIXED_ARRAY ? multiply(element, f.bound()) : element;
            size = size > Long.MAX_VALUE - fieldSize ? Long.MAX_VALUE : size + fieldSize;
        }
        path.remove(name);
        if (size == 0) {
            throw new DefinitionException(0, "type " + name + " takes no bytes on the wire (only empty arrays)");
        }
        known.put(name, size);
        return size;
    }

    private static long multiply(long a, long b) {
        return b != 0 && a > Long.MAX_VALUE / b ? Long.MAX_VALUE : a * b;
    }

    /** Nesting through sequences too (a message's depth on the wire is bounded by the decoder as well). */
    private static void depth(String name, Map<String, MessageType> types, int level, Map<String, Integer> seen)
            throws DefinitionException {
        if (level > MAX_NESTING) {
            throw new DefinitionException(0, "types nest deeper than " + MAX_NESTING + " levels (" + name + ")");
        }
        Integer before = seen.get(name);
        if (before != null && before <= level) {
            return; // already checked from as high up, or a recursion through a sequence
        }
        seen.put(name, level);
        for (Field f : types.get(name).fields()) {
            if (f.isMessage()) {
                depth(f.typeName(), types, level + 1, seen);
            }
        }
    }
}
