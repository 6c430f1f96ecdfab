package touchline.serve;

import io.netty.handler.codec.http.FullHttpRequest;
import io.netty.handler.codec.http.HttpResponseStatus;
import io.netty.handler.codec.http.QueryStringDecoder;

import java.util.List;

/**
 * Admits an HTTP request (the WebSocket upgrade) only with the server's token in its query,
 * {@code ?token=…}; anything else gets 401 and a closed connection, and is counted.
 */
final class TokenGate extends UpgradeGate {

    private final AccessToken token;

    TokenGate(AccessToken token, Refusals refusals) {
        super(refusals, Refusals.Reason.TOKEN, HttpResponseStatus.UNAUTHORIZED);
        this.token = token;
    }

    @Override
    String refusal(FullHttpRequest request) {
        List<String> presented = new QueryStringDecoder(request.uri()).parameters().get("token");
        return presented != null && presented.size() == 1 && token.admits(presented.get(0)) ? null
                : "this Touchline needs its token: ws://HOST:PORT/?token=...";
    }
}
