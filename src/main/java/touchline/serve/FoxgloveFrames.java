package touchline.serve;

import io.netty.buffer.ByteBuf;
import io.netty.buffer.ByteBufAllocator;
import io.netty.handler.codec.http.websocketx.BinaryWebSocketFrame;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import org.json.JSONArray;
import org.json.JSONObject;

import java.util.Collection;

/**
 * The server's side of the Foxglove WebSocket protocol ({@code foxglove.websocket.v1}) as
 * frames: the JSON ops (serverInfo, advertise, status) and the binary ones (message data,
 * time), integers little-endian as the spec says.
 */
final class FoxgloveFrames {

    static final byte MESSAGE_DATA = 0x01;
    static final byte TIME = 0x02;
    static final int STATUS_INFO = 0;
    static final int STATUS_WARNING = 1;
    static final int STATUS_ERROR = 2;

    private final String serverName;
    private final String sessionId;

    FoxgloveFrames(String serverName, String sessionId) {
        this.serverName = serverName;
        this.sessionId = sessionId;
    }

    TextWebSocketFrame serverInfo() {
        return text(new JSONObject().put("op", "serverInfo").put("name", serverName)
                .put("capabilities", new JSONArray().put("time")).put("supportedEncodings", new JSONArray())
                .put("metadata", new JSONObject()).put("sessionId", sessionId));
    }

    TextWebSocketFrame advertise(Collection<ServedChannel> channels) {
        JSONArray list = new JSONArray();
        channels.forEach(c -> list.put(c.advertisement()));
        return text(new JSONObject().put("op", "advertise").put("channels", list));
    }

    TextWebSocketFrame status(int level, String message) {
        return text(new JSONObject().put("op", "status").put("level", level).put("message", message));
    }

    /** A status answering the client's request {@code id} (Foxglove's status carries the id of what it answers). */
    TextWebSocketFrame status(int level, String message, String id) {
        return text(new JSONObject().put("op", "status").put("level", level).put("message", message).put("id", id));
    }

    BinaryWebSocketFrame messageData(ByteBufAllocator alloc, int subscriptionId, long timeNanos, byte[] payload) {
        ByteBuf b = alloc.buffer(13 + payload.length);
        b.writeByte(MESSAGE_DATA).writeIntLE(subscriptionId).writeLongLE(timeNanos).writeBytes(payload);
        return new BinaryWebSocketFrame(b);
    }

    BinaryWebSocketFrame time(ByteBufAllocator alloc, long timeNanos) {
        ByteBuf b = alloc.buffer(9);
        b.writeByte(TIME).writeLongLE(timeNanos);
        return new BinaryWebSocketFrame(b);
    }

    private static TextWebSocketFrame text(JSONObject o) {
        return new TextWebSocketFrame(o.toString());
    }
}
