package touchline.app.bridges;

import touchline.transport.remote.ServerProbe;

import javax.net.ssl.SSLContext;
import java.net.URI;
import java.time.Duration;

/**
 * What a lone {@code --connect URL} names: another Touchline (its server calls itself
 * "Touchline"; viewed, commands off) or a robot's Foxglove bridge (a robot of this console). A
 * server that cannot be asked (down, refusing without its token) is taken for a Touchline when
 * the URL carries a {@code token=} (Touchline's servers want one), else for a bridge, which is
 * then called again until it answers.
 */
public final class ServerKind {

    static final Duration WAIT = Duration.ofSeconds(5);
    static final String TOUCHLINE = "Touchline";

    private final URI url;
    private final SSLContext tls;

    public ServerKind(URI url, SSLContext tls) {
        this.url = url;
        this.tls = tls;
    }

    /** Whether the URL names another Touchline; asks its server (up to five seconds). */
    public boolean isTouchline() throws InterruptedException {
        return new ServerProbe(url, tls, WAIT).serverName().map(TOUCHLINE::equals)
                .orElseGet(() -> url.getRawQuery() != null && url.getRawQuery().contains("token="));
    }
}
