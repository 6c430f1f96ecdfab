package touchline.serve;

import org.json.JSONObject;
import touchline.proto.Fumanoid;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Each robot's debug text also as a standard {@code foxglove.Log} channel ({@code /robot/3/log},
 * JSON), so the viewers' own Log panel shows it without any Touchline code: the option's name is
 * the log's name, the text its message.
 */
final class DebugTextLog {

    static final String SCHEMA = """
            {"type":"object","properties":{\
            "timestamp":{"type":"object","properties":{"sec":{"type":"integer"},"nsec":{"type":"integer"}}},\
            "level":{"type":"integer"},"message":{"type":"string"},"name":{"type":"string"},\
            "file":{"type":"string"},"line":{"type":"integer"}}}""";
    private static final int INFO = 2;

    private final ChannelTable channels;
    private final Map<Integer, ServedChannel> byRobot = new ConcurrentHashMap<>();

    DebugTextLog(ChannelTable channels) {
        this.channels = channels;
    }

    /** Serves {@code e} on its robot's log channel when it is debug text from a robot. */
    void accept(Envelope e) {
        if (e.direction() != Direction.IN || !e.kind().equals(Fumanoid.debugText.getDescriptor().getName())) {
            return;
        }
        Fumanoid.DebugText text = e.extension(Fumanoid.debugText);
        ServedChannel c = channel(e.robotId());
        if (text == null || c == null) {
            return;
        }
        Subscription[] subscribers = c.subscribers();
        if (subscribers.length == 0) {
            return;
        }
        long nanos = e.timeMicros() * 1000;
        byte[] json = new JSONObject()
                .put("timestamp", new JSONObject().put("sec", Math.floorDiv(nanos, 1_000_000_000L))
                        .put("nsec", Math.floorMod(nanos, 1_000_000_000L)))
                .put("level", INFO).put("message", text.getText()).put("name", text.getOption())
                .put("file", "").put("line", 0).toString().getBytes(StandardCharsets.UTF_8);
        for (Subscription s : subscribers) {
            s.viewer().offer(s, nanos, json);
        }
    }

    private ServedChannel channel(int robotId) {
        ServedChannel c = byRobot.get(robotId);
        if (c != null) {
            return c;
        }
        synchronized (this) {
            c = byRobot.get(robotId);
            if (c == null) {
                String robot = robotId == Envelope.NO_ROBOT ? "unknown" : Integer.toString(robotId);
                c = channels.addJson("/robot/" + robot + "/log", "foxglove.Log", SCHEMA);
                if (c != null) {
                    byRobot.put(robotId, c);
                }
            }
            return c;
        }
    }
}
