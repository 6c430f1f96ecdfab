package touchline.serve;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketFrame;
import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;

import touchline.transport.MicrosClock;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What a viewer may ask: subscribe and unsubscribe. The server is read-only, so every other op
 * (publishing, parameters, services) and every binary client message is answered with an
 * error status and goes nowhere near a robot; so are garbage, unknown channels and reused ids.
 * Each refusal is counted; the connection stays open.
 */
final class ClientOps extends SimpleChannelInboundHandler<WebSocketFrame> {

    static final String READ_ONLY = "read-only server";

    private final ChannelTable channels;
    private final AtomicLong badRequests;
    private final MicrosClock clock;

    ClientOps(ChannelTable channels, AtomicLong badRequests, MicrosClock clock) {
        this.channels = channels;
        this.badRequests = badRequests;
        this.clock = clock;
    }

    @Override
    protected void channelRead0(ChannelHandlerContext ctx, WebSocketFrame frame) {
        Viewer viewer = ctx.channel().attr(ViewerSession.VIEWER).get();
        if (viewer == null) {
            return;
        }
        if (!(frame instanceof TextWebSocketFrame text)) {
            refuse(viewer, READ_ONLY + ": binary client messages are not accepted");
            return;
        }
        JSONObject op;
        try {
            op = new JSONObject(text.text());
        } catch (JSONException | StackOverflowError e) {
            refuse(viewer, "not a JSON object: " + e.getMessage());
            return;
        }
        String name = op.optString("op", null);
        if (name == null) {
            refuse(viewer, "a message without an \"op\"");
            return;
        }
        switch (name) {
            case "subscribe" -> subscribe(viewer, op);
            case "unsubscribe" -> unsubscribe(viewer, op);
            default -> refuse(viewer, READ_ONLY + ": op \"" + clip(name, 64) + "\" is not accepted");
        }
    }

    private void subscribe(Viewer viewer, JSONObject op) {
        JSONArray list = op.optJSONArray("subscriptions");
        if (list == null) {
            refuse(viewer, "subscribe without a \"subscriptions\" array");
            return;
        }
        for (int i = 0; i < list.length(); i++) {
            JSONObject s = list.optJSONObject(i);
            Long id = s == null ? null : uint32(s.opt("id"));
            Long channelId = s == null ? null : uint32(s.opt("channelId"));
            if (id == null || channelId == null) {
                refuse(viewer, "subscription " + i + " needs a numeric \"id\" and \"channelId\" (unsigned 32-bit)");
                continue;
            }
            Optional<ServedChannel> channel = channels.byId(channelId);
            if (channel.isEmpty()) {
                refuse(viewer, "unknown channel " + channelId);
                continue;
            }
            viewer.subscribe(id.intValue(), channel.get(), clock.nowMicros() * 1000)
                    .ifPresent(reason -> refuse(viewer, reason));
        }
    }

    private void unsubscribe(Viewer viewer, JSONObject op) {
        JSONArray ids = op.optJSONArray("subscriptionIds");
        if (ids == null) {
            refuse(viewer, "unsubscribe without a \"subscriptionIds\" array");
            return;
        }
        for (int i = 0; i < ids.length(); i++) {
            Long id = uint32(ids.opt(i));
            if (id == null) {
                refuse(viewer, "subscription id " + i + " is not an unsigned 32-bit number");
                continue;
            }
            viewer.unsubscribe(id.intValue()).ifPresent(reason -> refuse(viewer, reason));
        }
    }

    private static Long uint32(Object value) {
        if (value instanceof Number n) {
            double d = n.doubleValue();
            if (d >= 0 && d <= 0xFFFF_FFFFL && d == Math.rint(d)) {
                return (long) d;
            }
        }
        return null;
    }

    private static String clip(String s, int max) {
        return s.length() <= max ? s : s.substring(0, max) + "…";
    }

    private void refuse(Viewer viewer, String reason) {
        badRequests.incrementAndGet();
        viewer.status(FoxgloveFrames.STATUS_ERROR, clip(reason, 200));
    }
}
