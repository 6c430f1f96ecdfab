package touchline.serve;

import io.netty.channel.ChannelHandlerContext;
import io.netty.channel.SimpleChannelInboundHandler;
import io.netty.handler.codec.http.websocketx.TextWebSocketFrame;
import io.netty.handler.codec.http.websocketx.WebSocketFrame;
import org.json.JSONArray;
import org.json.JSONException;
import org.json.JSONObject;

import touchline.transport.MicrosClock;
import touchline.transport.SendResult;

import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What a viewer may ask: subscribe and unsubscribe; and, from this machine only and when the
 * console lets it ({@link OptionSwitch}), {@code switchOption} (Touchline's own op: {@code
 * {"op":"switchOption","robot":3,"option":"demo.text","on":true,"id":"1"}}, answered by a status
 * with that id: info sent, warning held back by match mode, error not sent). Every other op
 * (publishing, parameters, services) and every binary client message is answered with an
 * error status and goes nowhere near a robot; so are garbage, unknown channels and reused ids.
 * One client message gets at most one status, however many of its entries were refused, and
 * at most {@link #MAX_ENTRIES} of its entries are looked at. Each refused message is counted;
 * the connection stays open.
 */
final class ClientOps extends SimpleChannelInboundHandler<WebSocketFrame> {

    static final String READ_ONLY = "read-only server";
    /**
     * Entries of one subscribe or unsubscribe looked at; the rest of the frame is ignored and
     * said so. As many as there can be channels: a viewer never needs more in one message.
     */
    static final int MAX_ENTRIES = FoxgloveServer.MAX_CHANNELS;

    private final ChannelTable channels;
    private final AtomicLong badRequests;
    private final MicrosClock clock;
    private final java.util.function.Supplier<OptionSwitch> switches;

    /** {@code switches}: the console's option switch, or null while it offers none (a viewer's request is refused). */
    ClientOps(ChannelTable channels, AtomicLong badRequests, MicrosClock clock,
              java.util.function.Supplier<OptionSwitch> switches) {
        this.channels = channels;
        this.badRequests = badRequests;
        this.clock = clock;
        this.switches = switches;
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
            case "switchOption" -> switchOption(viewer, op);
            default -> refuse(viewer, READ_ONLY + ": op \"" + clip(name, 64) + "\" is not accepted");
        }
    }

    private void subscribe(Viewer viewer, JSONObject op) {
        JSONArray list = op.optJSONArray("subscriptions");
        if (list == null) {
            refuse(viewer, "subscribe without a \"subscriptions\" array");
            return;
        }
        Refused refused = new Refused("subscription", list.length());
        for (int i = 0; i < Math.min(list.length(), MAX_ENTRIES); i++) {
            JSONObject s = list.optJSONObject(i);
            Long id = s == null ? null : uint32(s.opt("id"));
            Long channelId = s == null ? null : uint32(s.opt("channelId"));
            if (id == null || channelId == null) {
                refused.add(i, "needs a numeric \"id\" and \"channelId\" (unsigned 32-bit)");
                continue;
            }
            Optional<ServedChannel> channel = channels.byId(channelId);
            if (channel.isEmpty()) {
                refused.add(i, "unknown channel " + channelId);
                continue;
            }
            viewer.subscribe(id.intValue(), channel.get(), clock.nowMicros() * 1000)
                    .ifPresent(reason -> refused.add(-1, reason));
        }
        refused.said().ifPresent(reason -> refuse(viewer, reason));
    }

    private void unsubscribe(Viewer viewer, JSONObject op) {
        JSONArray ids = op.optJSONArray("subscriptionIds");
        if (ids == null) {
            refuse(viewer, "unsubscribe without a \"subscriptionIds\" array");
            return;
        }
        Refused refused = new Refused("subscription id", ids.length());
        for (int i = 0; i < Math.min(ids.length(), MAX_ENTRIES); i++) {
            Long id = uint32(ids.opt(i));
            if (id == null) {
                refused.add(i, "not an unsigned 32-bit number");
                continue;
            }
            viewer.unsubscribe(id.intValue()).ifPresent(reason -> refused.add(-1, reason));
        }
        refused.said().ifPresent(reason -> refuse(viewer, reason));
    }

    private void switchOption(Viewer viewer, JSONObject op) {
        String id = clip(op.optString("id", ""), 64);
        OptionSwitch s = switches.get();
        String why = s == null ? READ_ONLY + ": this console switches no options for viewers"
                : !viewer.local() ? "options are switched only from this machine (a tool on loopback)"
                : viewer.webPage() ? "options are not switched from a web page (only by a tool on this machine, e.g."
                        + " touchline options --connect)"
                : !(op.opt("robot") instanceof Number) || uint32(op.opt("robot")) == null ? "switchOption needs a numeric \"robot\""
                : op.optString("option", "").isEmpty() ? "switchOption needs an \"option\""
                : !(op.opt("on") instanceof Boolean) ? "switchOption needs \"on\": true or false" : null;
        if (why != null) {
            badRequests.incrementAndGet();
            viewer.answer(FoxgloveFrames.STATUS_ERROR, why, id);
            return;
        }
        SendResult r = s.switchOption(uint32(op.opt("robot")).intValue(), clip(op.getString("option"), 200),
                op.getBoolean("on"));
        int level = switch (r.outcome()) {
            case SENT -> FoxgloveFrames.STATUS_INFO;
            case HELD -> FoxgloveFrames.STATUS_WARNING;
            case FAILED -> FoxgloveFrames.STATUS_ERROR;
        };
        viewer.answer(level, clip(r.reason(), 400), id);
    }

    /**
     * The entries of one subscribe or unsubscribe refused, told in one status: a frame of many
     * bad entries costs one reply, not one each (issue 37).
     */
    private static final class Refused {
        private final String what;
        private final int entries;
        private final StringBuilder first = new StringBuilder();
        private int count;

        Refused(String what, int entries) {
            this.what = what;
            this.entries = entries;
        }

        /** Entry {@code index} (-1: the reason names it) refused for {@code reason}. */
        void add(int index, String reason) {
            if (count++ == 0) {
                first.append(index < 0 ? "" : what + " " + index + ": ").append(reason);
            }
        }

        Optional<String> said() {
            String beyond = entries <= MAX_ENTRIES ? ""
                    : (count == 0 ? "" : "; ") + "the " + (entries - MAX_ENTRIES) + " entries beyond the first "
                    + MAX_ENTRIES + " ignored";
            if (count == 0 && beyond.isEmpty()) {
                return Optional.empty();
            }
            String refused = count == 0 ? "" : count == 1 ? first.toString()
                    : count + " of " + Math.min(entries, MAX_ENTRIES) + " entries refused, the first: " + first;
            return Optional.of(refused + beyond);
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
