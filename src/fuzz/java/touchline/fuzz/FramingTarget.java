package touchline.fuzz;

import touchline.protocol.DatagramClass;
import touchline.protocol.FrameCodec;
import touchline.protocol.FrameResult;
import touchline.protocol.Framing;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;

import java.util.Arrays;
import java.util.List;

/** Datagram framing: the header comes off, and a frame encoded again frames the same payload. */
final class FramingTarget implements FuzzTarget {

    private final FrameCodec frames = new FrameCodec();

    @Override
    public String name() {
        return "framing";
    }

    @Override
    public void accept(byte[] input) {
        DatagramClass.of(input, input.length);
        if (frames.decode(input) instanceof FrameResult.Frame frame) {
            FuzzTarget.check(frame.payload().length <= FrameCodec.MAX_DATAGRAM, "payload larger than a datagram");
            byte[] again = frames.encode(frame.framing(), frame.payload());
            FuzzTarget.check(frames.decode(again) instanceof FrameResult.Frame f2 && f2.framing() == frame.framing()
                    && Arrays.equals(f2.payload(), frame.payload()), "a decoded frame does not survive encode/decode");
        }
    }

    @Override
    public List<byte[]> seeds() {
        MessageCodec codec = new MessageCodec(new MessageKinds());
        byte[] request = codec.optionRequest("demo.text", true).toByteArray();
        return List.of(frames.encode(Framing.LEGACY, request), frames.encode(Framing.LENGTH_PREFIX, request),
                frames.encode(Framing.LENGTH_PREFIX, new byte[0]), new byte[]{0, 42});
    }
}
