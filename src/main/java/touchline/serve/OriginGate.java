package touchline.serve;

import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.HttpHeaderNames;
import io.netty.handler.codec.http.HttpResponseStatus;

/**
 * Admits the WebSocket upgrade of a tool (no {@code Origin} header: Foxglove's and Lichtblick's
 * desktop apps, scripts, another Touchline) or of a web page whose origin is allowed
 * ({@link AllowedOrigins}); any other web page open in the laptop's browser gets 403 and a
 * closed connection, counted, so it cannot read the team's stream from {@code ws://127.0.0.1}.
 */
final class OriginGate extends UpgradeGate {

    private final AllowedOrigins allowed;

    OriginGate(AllowedOrigins allowed, Refusals refusals) {
        super(refusals, Refusals.Reason.ORIGIN, HttpResponseStatus.FORBIDDEN);
        this.allowed = allowed;
    }

    @Override
    String refusal(FullHttpRequest request) {
        String origin = request.headers().get(HttpHeaderNames.ORIGIN);
        if (origin == null || allowed.admits(origin)) {
            return null;
        }
        String shown = AllowedOrigins.clip(origin);
        return "a web page from " + shown + " may not watch this Touchline (start serve with --allow-origin "
                + shown + " to allow it)";
    }
}
