package touchline.cli;

import touchline.protocol.Hex;
import touchline.protocol.MessageText;
import touchline.transport.Envelope;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;

/** One line of text per Envelope, for {@code listen} and headless replay. */
public final class EnvelopeLine {

    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss.SSS").withZone(ZoneId.systemDefault());
    private final MessageText text = new MessageText();
    private final Hex hex = new Hex();

    public String format(Envelope e) {
        StringBuilder b = new StringBuilder(160);
        b.append(TIME.format(Instant.ofEpochSecond(0, e.timeMicros() * 1000))).append(' ')
                .append(e.direction() == touchline.transport.Direction.IN ? "IN  " : "OUT ")
                .append(e.channel().name().toLowerCase()).append(' ');
        if (e.robotId() >= 0) {
            b.append("robot ").append(e.robotId()).append(' ');
        }
        b.append(e.peer() == null ? "-" : e.peerText()).append(' ');
        if (e.isMalformed()) {
            return b.append("MALFORMED (").append(e.size()).append(" bytes): ").append(e.error())
                    .append(" [").append(hex.dump(e.raw(), 16).replace('\n', ' ')).append(']').toString();
        }
        b.append(e.kind()).append(' ');
        if (e.message() != null) {
            b.append(text.renderLine(e.message()));
        } else if (e.ros() != null) {
            b.append(e.ros().typeName()).append(' ').append(e.ros().line(400));
        } else if (e.channel() == touchline.transport.Channel.FOREIGN) {
            // another tool's JSON channel: the bytes are the text
            String json = new String(e.raw(), java.nio.charset.StandardCharsets.UTF_8).replace('\n', ' ');
            b.append(json.length() > 400 ? json.substring(0, 400) + "…" : json);
        } else {
            b.append('(').append(e.size()).append(" bytes) ").append(hex.dump(e.raw(), 24).replace('\n', ' '));
        }
        return b.toString();
    }
}
