package touchline.transport.gamecontroller;

import touchline.game.MatchMode;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;

import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * Listens to the game-state port (3838) when the console does not run the GameController
 * itself, e.g. at a tournament: every game-state packet becomes an IN envelope, and its state
 * feeds {@link MatchMode}, so the console falls silent while the official GameController says
 * READY, SET or PLAYING. Packets in no known format are published with an error, never thrown.
 */
public final class GameStateWatch implements AutoCloseable {

    private final KnownGameStateFormats formats = new KnownGameStateFormats();
    private final EnvelopeSink sink;
    private final MatchMode matchMode;
    private final GcListener listener;

    /**
     * @param bind      usually 0.0.0.0:3838 (shared with SO_REUSEADDR)
     * @param sink      receives one GAMECONTROLLER envelope per game-state datagram
     * @param matchMode told each decoded state
     */
    public GameStateWatch(InetSocketAddress bind, EnvelopeSink sink, MatchMode matchMode) throws IOException {
        this.sink = sink;
        this.matchMode = matchMode;
        this.listener = new GcListener(bind, this::onDatagram, "gc-watch");
    }

    public InetSocketAddress localAddress() throws IOException {
        return listener.localAddress();
    }

    private void onDatagram(byte[] data, InetSocketAddress from) {
        if (!KnownGameStateFormats.isGameState(data)) {
            return; // robots' own broadcasts on the shared port are somebody else's business
        }
        KnownGameStateFormats.Match m = formats.decode(data);
        sink.accept(new Envelope(Clock.micros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                m == null ? "gc.unknown" : m.format().kind(), null, data,
                m == null ? "game-state packet in no known format" : null));
        if (m != null) {
            matchMode.observe(m.data().state(), "GameController at " + from.getAddress().getHostAddress() + ":"
                    + from.getPort());
        }
    }

    @Override
    public void close() {
        listener.close();
    }
}
