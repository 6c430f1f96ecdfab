package touchline.record;

import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What a replay shows at one moment: the newest envelope of each file, direction, channel, robot
 * and message kind at or before it, in the order they were recorded. A seek delivers these first,
 * so every view shows the state at the play head (paused, too) instead of nothing until each kind
 * comes round again. Reads the session from its start to the moment (about a second per recorded
 * hour), on the player's thread.
 */
final class PlayHead {

    /** One envelope of the state and the file it comes from ("" for a single file). */
    record Newest(Envelope envelope, String source) { }

    private record Key(String source, Direction direction, Channel channel, int robotId, String kind) { }

    private final ReplaySession session;

    PlayHead(ReplaySession session) {
        this.session = session;
    }

    /** The newest envelope of each kind at or before {@code micros}, oldest first. */
    List<Newest> at(long micros) {
        Map<Key, Newest> newest = new LinkedHashMap<>();
        ReplaySession.Cursor cursor = session.cursor(Long.MIN_VALUE);
        for (Envelope e = cursor.next(); e != null && e.timeMicros() <= micros; e = cursor.next()) {
            Key key = new Key(cursor.source(), e.direction(), e.channel(), e.robotId(), e.kind());
            newest.remove(key); // re-inserted: the map keeps the order of each kind's newest
            newest.put(key, new Newest(e, cursor.source()));
        }
        return new ArrayList<>(newest.values());
    }
}
