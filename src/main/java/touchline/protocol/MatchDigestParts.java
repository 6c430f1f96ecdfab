package touchline.protocol;

import touchline.proto.Fumanoid;

import java.util.ArrayList;
import java.util.List;

/**
 * Takes a robot's match digest (extension 51, docs/protocol.md "Match digest") apart into the
 * messages it carries: the Status, then each item as the robot would have streamed it outside
 * play (a whole {@code Message} with its robotID and one extension). Each part has its own kind
 * and bytes, so every view shows a digest exactly as streamed data. Pure: no sockets, no threads.
 */
public final class MatchDigestParts {

    /** One message out of a digest: its kind ({@code status}, {@code debugPlot}, {@code ext#1042}…), the message, its bytes. */
    public record Part(String kind, Fumanoid.Message message, byte[] bytes) {
    }

    private final MessageKinds kinds;

    public MatchDigestParts(MessageKinds kinds) {
        this.kinds = kinds;
    }

    /** The parts of {@code message}'s digest, Status first; empty when it carries none. */
    public List<Part> of(Fumanoid.Message message) {
        if (!message.hasExtension(Fumanoid.matchDigest)) {
            return List.of();
        }
        Fumanoid.MatchDigest digest = message.getExtension(Fumanoid.matchDigest);
        List<Part> parts = new ArrayList<>(digest.getItemsCount() + 1);
        if (digest.hasStatus()) {
            Fumanoid.Message status = Fumanoid.Message.newBuilder().setRobotID(message.getRobotID())
                    .setExtension(Fumanoid.status, digest.getStatus()).build();
            parts.add(new Part(kinds.kindOf(Fumanoid.status.getNumber()), status, status.toByteArray()));
        }
        for (Fumanoid.Message item : digest.getItemsList()) {
            byte[] bytes = item.toByteArray();
            int extension = MessageCodec.firstExtension(bytes);
            parts.add(new Part(extension == 0 ? "empty" : kinds.kindOf(extension), item, bytes));
        }
        return parts;
    }
}
