package touchline.fuzz;

import com.google.protobuf.ByteString;
import com.google.protobuf.InvalidProtocolBufferException;
import touchline.proto.Nao;
import touchline.protocol.MessageText;
import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;

import java.util.List;

/**
 * A NAO reply (no size cap on the wire): parsed, rendered as text within its cap, its return
 * value decoded to Java values; a decoded value encodes back to one that decodes the same.
 */
final class MixedValueTarget implements FuzzTarget {

    private static final int MAX_TEXT = MessageText.MAX_CHARS + 200;

    private final MixedValueCodec codec = new MixedValueCodec();
    private final MessageText text = new MessageText();

    @Override
    public String name() {
        return "mixed-value";
    }

    @Override
    public void accept(byte[] input) {
        reply(input);
        if (input.length > 0) {
            // the rest of the input nested (first byte × 8) levels deep inside the return value
            ByteString rest = ByteString.copyFrom(input, 1, input.length - 1);
            reply(Nao.HAWActorRPCResponse.newBuilder().setReturnval(Nao.MixedValue.newBuilder()
                    .setUnknownFields(Samples.nestedUnknown((input[0] & 0xFF) * 8, rest))).build().toByteArray());
        }
    }

    private void reply(byte[] input) {
        Nao.HAWActorRPCResponse reply;
        try {
            reply = Nao.HAWActorRPCResponse.parseFrom(input);
        } catch (InvalidProtocolBufferException e) {
            return;
        }
        FuzzTarget.check(text.render(reply).length() <= MAX_TEXT, "reply text over the cap");
        if (!reply.hasReturnval()) {
            return;
        }
        Object value;
        try {
            value = codec.decode(reply.getReturnval());
        } catch (MixedValueException e) {
            return;
        }
        String shown = MixedValueCodec.format(value);
        Object again = codec.decode(codec.encode(value));
        FuzzTarget.check(shown.equals(MixedValueCodec.format(again)), "round trip changed " + shown);
    }

    @Override
    public List<byte[]> seeds() {
        return new Samples().naoReplies();
    }
}
