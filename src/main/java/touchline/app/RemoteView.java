package touchline.app;

import touchline.transport.remote.RemoteStatus;
import touchline.transport.remote.RemoteStream;

import javax.net.ssl.SSLContext;
import java.net.URI;
import java.time.Duration;
import java.util.Optional;

/**
 * Watching another Touchline (its {@code touchline serve}, or its window serving to viewers)
 * instead of the field: its robots' envelopes enter this console's stream marked
 * {@link touchline.transport.Origin#REMOTE}, so every view works as on live robots, and from then
 * on every command is refused with {@link RemoteView#COMMANDS_OFF}.
 */
public final class RemoteView {

    /** Why a console viewing another Touchline's stream sends nothing: every command path says this. */
    public static final String COMMANDS_OFF = "viewing a remote Touchline: commands are off";

    private final LiveField field;
    private final Referee referee;
    private final FieldGate gate;
    private volatile RemoteStream remote;

    RemoteView(LiveField field, Referee referee, FieldGate gate) {
        this.field = field;
        this.referee = referee;
        this.gate = gate;
    }

    /**
     * Starts viewing {@code url}: every command is refused from now on (debug options, the
     * reliable stream, the GameController) — the remote console is the one talking to the robots.
     * The connection reconnects by itself; its status is {@link #status()}'s. The remote console's
     * GameController packets, NAO frames and malformed datagrams come too (as their bytes), and
     * its GameController's state drives this console's match mode.
     *
     * @param tls trust for a {@code wss://} server, or null
     */
    public synchronized RemoteStream view(URI url, SSLContext tls) {
        if (remote != null) {
            remote.close();
        }
        gate.shut();
        referee.stop();
        // the remote field's GameController drives this console's match mode (shown; nothing is sent anyway)
        remote = new RemoteStream(url, tls, field.codec(), new RemoteGameState(referee.matchMode(), field.live()),
                Duration.ofSeconds(5));
        return remote.start();
    }

    /** The connection to the remote Touchline this console views, in words and figures, if it views one. */
    public Optional<RemoteStatus> status() {
        return stream().map(RemoteStream::status);
    }

    /** The remote Touchline this console views, if it views one. */
    public Optional<RemoteStream> stream() {
        return Optional.ofNullable(remote);
    }

    /** True while this console views a remote Touchline. */
    public boolean viewing() {
        return remote != null;
    }

    void close() {
        RemoteStream r = remote;
        if (r != null) {
            r.close();
        }
    }
}
