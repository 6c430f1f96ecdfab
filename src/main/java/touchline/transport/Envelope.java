package touchline.transport;

import com.google.protobuf.Message;
import touchline.security.Authenticity;

import java.net.InetSocketAddress;
import java.util.Arrays;
import java.util.Objects;

/**
 * One datagram or call as it crossed the console's boundary, time-stamped when it did.
 * Everything the console sees or sends, live or replayed, travels as an Envelope: the
 * model, the recorder, the CLI and (through the model) the UI consume this one stream.
 *
 * @param timeMicros   receive (or send) time, microseconds since the epoch
 * @param direction    inbound from a robot or outbound from the console
 * @param channel      which wire protocol carried it
 * @param peer         the robot's (or GameController's) address; null when unknown
 * @param robotId      the robot's ID, or {@link #NO_ROBOT} when the bytes do not say
 * @param kind         the message identity, e.g. {@code status}, {@code ext#1042}, {@code malformed}
 * @param message      the decoded protobuf message, or null when there is none
 * @param raw          the exact bytes on the wire (never null)
 * @param error        why the bytes could not be decoded, or null when they could
 * @param origin       live traffic, or a recording played back (which must never act on the live field)
 * @param authenticity whether a robot's datagram carried a right tag of the team key (docs/security.md);
 *                     {@code NOT_CHECKED} for everything that is not a robot's datagram
 * @param matchPart    one message taken out of a robot's match digest (its Status or an item): match data
 *                     shown like streamed data; {@code raw} is then the part's own bytes, and the datagram
 *                     itself travels as its own envelope (what counts traffic or records takes that one)
 */
public record Envelope(long timeMicros, Direction direction, Channel channel, InetSocketAddress peer,
                       int robotId, String kind, Message message, byte[] raw, String error, Origin origin,
                       Authenticity authenticity, boolean matchPart) {

    public static final int NO_ROBOT = -1;

    public Envelope {
        Objects.requireNonNull(direction, "direction");
        Objects.requireNonNull(channel, "channel");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(raw, "raw");
        Objects.requireNonNull(origin, "origin");
        Objects.requireNonNull(authenticity, "authenticity");
    }

    /** A whole datagram or call (not a part of a match digest). */
    public Envelope(long timeMicros, Direction direction, Channel channel, InetSocketAddress peer,
                    int robotId, String kind, Message message, byte[] raw, String error, Origin origin,
                    Authenticity authenticity) {
        this(timeMicros, direction, channel, peer, robotId, kind, message, raw, error, origin, authenticity, false);
    }

    /** An envelope whose authenticity was not checked (outbound, GameController, NAO, older recordings). */
    public Envelope(long timeMicros, Direction direction, Channel channel, InetSocketAddress peer,
                    int robotId, String kind, Message message, byte[] raw, String error, Origin origin) {
        this(timeMicros, direction, channel, peer, robotId, kind, message, raw, error, origin, Authenticity.NOT_CHECKED);
    }

    /** A live envelope: what the transports and the console's own senders publish. */
    public Envelope(long timeMicros, Direction direction, Channel channel, InetSocketAddress peer,
                    int robotId, String kind, Message message, byte[] raw, String error) {
        this(timeMicros, direction, channel, peer, robotId, kind, message, raw, error, Origin.LIVE);
    }

    /** The same envelope marked as played back from a recording. */
    public Envelope asReplayed() {
        return origin == Origin.REPLAY ? this
                : new Envelope(timeMicros, direction, channel, peer, robotId, kind, message, raw, error, Origin.REPLAY,
                        authenticity, matchPart);
    }

    /** True when a recording played this envelope back: it must never cause a datagram or change match mode. */
    public boolean replayed() {
        return origin == Origin.REPLAY;
    }

    /**
     * The inbound or outbound FUmanoids message's extension of this kind, or null when the
     * envelope carries another kind. The kind (a string compare) is checked first: asking a
     * message for an extension costs a descriptor check, and each subscriber asks for every
     * datagram.
     */
    public <T> T extension(com.google.protobuf.GeneratedMessage.GeneratedExtension<touchline.proto.Fumanoid.Message, T> ext) {
        if (message instanceof touchline.proto.Fumanoid.Message m && kind.equals(ext.getDescriptor().getName())
                && m.hasExtension(ext)) {
            return m.getExtension(ext);
        }
        return null;
    }

    /**
     * The peer as a person reads it: {@code 10.0.0.7:10001}, or the host name as given when the
     * address was never resolved (a NAO's link names its host without a lookup); "" when unknown.
     */
    public String peerText() {
        return peer == null ? "" : peer.getHostString() + ":" + peer.getPort();
    }

    public boolean isMalformed() {
        return error != null;
    }

    public int size() {
        return raw.length;
    }

    /** The same datagram at the same moment; the authenticity mark is the console's verdict, not recorded, so not compared. */
    @Override
    public boolean equals(Object o) {
        return o instanceof Envelope e && timeMicros == e.timeMicros && robotId == e.robotId
                && direction == e.direction && channel == e.channel && origin == e.origin && matchPart == e.matchPart
                && Objects.equals(peer, e.peer)
                && kind.equals(e.kind) && Objects.equals(error, e.error) && Arrays.equals(raw, e.raw);
    }

    @Override
    public int hashCode() {
        return Objects.hash(timeMicros, direction, channel, robotId, kind, Arrays.hashCode(raw));
    }

    @Override
    public String toString() {
        return "Envelope[" + (origin == Origin.REPLAY ? "replayed " : "") + (matchPart ? "match " : "")
                + (authenticity == Authenticity.NOT_CHECKED ? "" : authenticity.word() + " ") + direction + " " + channel + " " + kind
                + " robot=" + robotId + " peer=" + peer + " bytes=" + raw.length + (error == null ? "" : " error=" + error) + "]";
    }
}
