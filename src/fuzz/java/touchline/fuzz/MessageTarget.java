package touchline.fuzz;

import touchline.protocol.DebugData;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.protocol.MessageResult;
import touchline.protocol.MessageText;

import java.util.List;

/**
 * A FUmanoids payload decoded, its debug data and option read, and rendered as text both ways,
 * as the network console and {@code listen} show it. The text must stay within its cap.
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
