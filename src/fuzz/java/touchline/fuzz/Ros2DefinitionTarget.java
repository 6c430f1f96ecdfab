package touchline.fuzz;

import touchline.protocol.ros2.CdrDecoder;
import touchline.protocol.ros2.DecodeResult;
import touchline.protocol.ros2.DefinitionParser;
import touchline.protocol.ros2.DefinitionResult;
import touchline.protocol.ros2.Ros2Sources;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * A ROS 2 schema from outside (a bag's, a bridge's advertise): the first byte chooses ros2msg
 * (even) or ros2idl (odd), the rest is the text. It parses or is refused with a reason naming a
 * line within the text; a definition it hands out decodes the input's own bytes as a message
 * without throwing, and every type a field names is in it.
 */
final class Ros2DefinitionTarget implements FuzzTarget {

    private final DefinitionParser parser = new DefinitionParser();

    @Override
    public String name() {
        return "ros2-definition";
    }

    @Override
    public void accept(byte[] input) {
        if (input.length == 0) {
            return;
        }
        String encoding = (input[0] & 1) == 0 ? "ros2msg" : "ros2idl";
        String text = new String(input, 1, input.length - 1, StandardCharsets.UTF_8);
        DefinitionResult r = parser.parse("fuzz_msgs/msg/Root", encoding, text);
        if (r instanceof DefinitionResult.Refused refused) {
            FuzzTarget.check(!refused.reason().isBlank(), "a refusal without a reason");
            FuzzTarget.check(refused.line() >= 0 && refused.line() <= text.split("\n", -1).length + 1,
                    "a refusal names line " + refused.line() + " of a text of fewer lines");
            return;
        }
        var definition = ((DefinitionResult.Parsed) r).definition();
        definition.types().values().forEach(t -> t.fields().forEach(f -> FuzzTarget.check(
                !f.isMessage() || definition.type(f.typeName()) != null, "an undefined type " + f.typeName())));
        byte[] message = new byte[input.length + 3];
        message[1] = 1;
        System.arraycopy(input, 0, message, 4, input.length - 1);
        DecodeResult d = new CdrDecoder(definition).decode(message);
        if (d instanceof DecodeResult.Decoded decoded) {
            FuzzTarget.check(decoded.message().line(500).length() <= 500, "a line over its cap");
        }
    }

    @Override
    public List<byte[]> seeds() {
        List<byte[]> out = new ArrayList<>();
        for (String t : Ros2CdrTarget.TYPES) {
            out.add(withPrefix(0, Ros2Sources.definition(t)));
        }
        out.add(withPrefix(1, Ros2CdrTarget.IDL));
        return out;
    }

    private static byte[] withPrefix(int first, String text) {
        byte[] t = text.getBytes(StandardCharsets.UTF_8);
        byte[] out = new byte[t.length + 1];
        out[0] = (byte) first;
        System.arraycopy(t, 0, out, 1, t.length);
        return out;
    }
}
