package touchline.transport.nao;

import com.google.protobuf.InvalidProtocolBufferException;
import touchline.proto.Nao.HAWActorRPCResponse;
import touchline.protocol.nao.MixedValueCodec;
import touchline.protocol.nao.MixedValueException;

import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Reads what the robot's RPC module sends back: the frames {@code [8-byte request id][empty]
 * [HAWActorRPCResponse]} become the request id and the response, and a response becomes the
 * call's {@link CallOutcome}. Anything unreadable (wrong frames, a response that does not
 * parse, a return value the codec refuses) is a value with the reason, counted, never an
 * exception. Pure: bytes in, values out.
 */
public final class ReplyReader {

    public ReplyReader() {
    }

    /** What a reply's frames were. */
    sealed interface Read {
    }

    /** A readable reply to request {@code id}. */
    record Reply(long id, HAWActorRPCResponse response) implements Read {
    }

    /** Unreadable frames; {@code id} is the request they name, or -1 when even that is unknown. */
    record Malformed(long id, String why, String callError) implements Read {
    }

    private final MixedValueCodec codec = new MixedValueCodec();
    private final AtomicLong malformed = new AtomicLong();

    Read read(List<byte[]> frames) {
        byte[] payload = frames.get(frames.size() - 1);
        if (frames.size() != 3 || frames.get(0).length != 8 || frames.get(1).length != 0) {
            malformed.incrementAndGet();
            return new Malformed(-1, "expected [8-byte id][empty][reply], got " + frames.size() + " frames", null);
        }
        long id = ByteBuffer.wrap(frames.get(0)).getLong();
        try {
            return new Reply(id, HAWActorRPCResponse.parseFrom(payload));
        } catch (InvalidProtocolBufferException e) {
            malformed.incrementAndGet();
            return new Malformed(id, "unreadable HAWActorRPCResponse: " + e.getMessage(),
                    "unreadable reply: " + e.getMessage());
        }
    }

    /** The outcome a response gives its call: the robot's error, "done", or the decoded value. */
    public CallOutcome outcomeOf(HAWActorRPCResponse response) {
        if (response.hasError()) {
            return new CallOutcome.Failed(response.getError());
        }
        if (!response.hasReturnval()) {
            return new CallOutcome.Done();
        }
        try {
            return new CallOutcome.Value(codec.decode(response.getReturnval()));
        } catch (MixedValueException e) {
            malformed.incrementAndGet();
            return new CallOutcome.Failed("unreadable return value: " + e.getMessage());
        }
    }

    /** Replies (or return values) that could not be read. */
    long malformed() {
        return malformed.get();
    }
}
