package touchline.protocol.ros2;

import java.util.Map;

/**
 * A parsed schema: the root type a channel carries and every type it depends on, by full
 * name ({@code pkg/msg/Type}; IDL's {@code pkg::msg::Type} is named the same way). Every
 * field's message type is among {@link #types()}: the parser checks that before it hands one
 * out. Immutable.
 */
public record MessageDefinition(String rootName, Map<String, MessageType> types) {

    public MessageDefinition {
        types = Map.copyOf(types);
        if (!types.containsKey(rootName)) {
            throw new IllegalArgumentException("no root type " + rootName);
        }
    }

    public MessageType root() {
        return types.get(rootName);
    }

    /** The type named {@code name}, or null. */
    public MessageType type(String name) {
        return types.get(name);
    }
}
