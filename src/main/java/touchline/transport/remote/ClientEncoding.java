package touchline.transport.remote;

import org.json.JSONArray;
import org.json.JSONObject;
import touchline.protocol.ros2.CdrEncoder;
import touchline.protocol.ros2.DefinitionParser;
import touchline.protocol.ros2.DefinitionResult;
import touchline.protocol.ros2.EncodeResult;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * How a message a person typed (JSON field values) goes to one Foxglove server, by the
 * encodings its {@code serverInfo} says it takes ({@code supportedEncodings}): CDR, written by the
 * type's ROS 2 definition ({@link CdrEncoder}), when the server takes {@code cdr} and either not
 * {@code json} or the definition is known (a ROS 2 robot then gets the bytes its own nodes
 * send); else the JSON text as typed. A server that lists no encodings gets JSON, as before.
 */
final class ClientEncoding {

    private final List<String> supported = new ArrayList<>();

    ClientEncoding(JSONObject serverInfo) {
        JSONArray list = serverInfo.optJSONArray("supportedEncodings");
        for (int i = 0; list != null && i < list.length(); i++) {
            supported.add(list.optString(i));
        }
    }

    /**
     * @param typeName the message's type as the user named it
     * @param ros2     the ROS 2 definition known for it, or null
     * @param required the encoding the server asks for this message (a service's request), or "" to choose
     * @param json     the values as typed
     */
    Outgoing write(String typeName, BridgedSchema ros2, String required, String json) {
        String encoding = !required.isEmpty() ? required
                : supported.contains("cdr") && (!supported.contains("json") || ros2 != null) ? "cdr"
                : supported.isEmpty() || supported.contains("json") ? "json" : "";
        return switch (encoding) {
            case "json" -> new Outgoing.Ready("json", null, json.getBytes(StandardCharsets.UTF_8));
            case "cdr" -> cdr(typeName, ros2, json);
            case "" -> new Outgoing.Refused("the robot takes only " + String.join(", ", supported)
                    + ", which Touchline does not write");
            default -> new Outgoing.Refused("the robot asks for " + encoding + ", which Touchline does not write");
        };
    }

    private static Outgoing cdr(String typeName, BridgedSchema ros2, String json) {
        if (ros2 == null || !ros2.isRos2()) {
            return new Outgoing.Refused("the robot takes CDR, and no ROS 2 definition of " + typeName
                    + " is known (it advertises no topic of that type)");
        }
        DefinitionResult parsed = new DefinitionParser().parse(ros2.schemaName(), ros2.schemaEncoding(),
                new String(ros2.schemaData(), StandardCharsets.UTF_8));
        if (parsed instanceof DefinitionResult.Refused r) {
            return new Outgoing.Refused("the definition of " + ros2.schemaName() + " does not parse: " + r.reason());
        }
        EncodeResult e = new CdrEncoder(((DefinitionResult.Parsed) parsed).definition()).encode(json);
        if (e instanceof EncodeResult.Refused r) {
            return new Outgoing.Refused(ros2.schemaName() + ": " + r.reason());
        }
        return new Outgoing.Ready("cdr", ros2, ((EncodeResult.Encoded) e).bytes());
    }
}
