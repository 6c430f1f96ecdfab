package touchline.fuzz;

import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;
import touchline.protocol.nao.ParamSyntax;

import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * A typed NAO parameter as a user types or pastes it: read, or refused with a message that
 * says where; a value that is read either encodes as a MixedValue or is refused by its codec.
 */
final class ParamSyntaxTarget implements FuzzTarget {

    private final MixedValueCodec codec = new MixedValueCodec();

    @Override
    public String name() {
        return "nao-param";
    }

    @Override
    public void accept(byte[] input) {
        String text = new String(input, StandardCharsets.UTF_8);
        parse(text);
        if (input.length > 0) {
            // the text inside (first byte × 8) opening brackets, a depth mutation seldom reaches
            parse("[".repeat((input[0] & 0xFF) * 8) + text.substring(1));
        }
    }

    private void parse(String text) {
        Object value;
        try {
            value = ParamSyntax.parse(text);
        } catch (IllegalArgumentException e) {
            FuzzTarget.check(e.getMessage() != null && e.getMessage().contains("column"), "an error that says not where");
            return;
        }
        try {
            codec.encode(value);
        } catch (MixedValueException e) {
            // declared: a value that cannot travel (a negative int, nesting beyond the codec's limit)
        }
    }

    @Override
    public List<byte[]> seeds() {
        return List.of("[HeadYaw, [0.5, 1], [], \"a b\"]", "42", "-1.25e3f", "true", "hello world", "\"q\\\"uote\"",
                "[[[1]], 2.5, \"x\"]").stream().map(s -> s.getBytes(StandardCharsets.UTF_8)).toList();
    }
}
