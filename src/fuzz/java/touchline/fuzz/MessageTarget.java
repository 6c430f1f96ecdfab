package touchline.fuzz;

import com.google.protobuf.ByteString;
import touchline.proto.Fumanoid;
import touchline.protocol.DebugData;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.protocol.MessageText;

import java.util.List;

/**
 * A FUmanoids payload decoded, its debug data and option read, and rendered as text both ways,
 * as the network console and {@code listen} show it. The text must stay within its cap. Each
 * input is also tried nested deep inside a known message, where mutation alone seldom goes.
 */
final class MessageTarget implements FuzzTarget {

    // the cap plus the marker line
    private static final int MAX_TEXT = MessageText.MAX_CHARS + 200;

    private final MessageKinds kinds = new MessageKinds();
    private final MessageCodec codec = new MessageCodec(kinds);
    private final DebugData debugData = new DebugData(kinds);
    private final MessageText text = new MessageText();

    @Override
    public String name() {
        return "message";
    }

    @Override
    public void accept(byte[] input) {
        decodeAndRender(input);
        if (input.length > 0) {
            // the rest of the input nested (first byte × 8) levels deep inside a known Status
            ByteString rest = ByteString.copyFrom(input, 1, input.length - 1);
            decodeAndRender(Fumanoid.Message.newBuilder().setRobotID(1).setExtension(Fumanoid.status,
                    Fumanoid.Status.newBuilder().setUnknownFields(Samples.nestedUnknown((input[0] & 0xFF) * 8, rest))
                            .build()).build().toByteArray());
        }
    }

    private void decodeAndRender(byte[] input) {
        if (codec.decode(input) instanceof MessageResult.Decoded d) {
            debugData.dataOf(d.kind(), d.message());
            debugData.optionOf(d.kind(), d.message());
            String rendered = text.render(d.message());
            FuzzTarget.check(rendered.length() <= MAX_TEXT, "text of " + rendered.length() + " characters");
            FuzzTarget.check(text.renderLine(d.message()).indexOf('\n') < 0, "a line with a line break");
        }
    }

    @Override
    public List<byte[]> seeds() {
        return new Samples().messages();
    }
}
