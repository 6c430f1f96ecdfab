package touchline.app.game;

import touchline.transport.gamecontroller.MonitorRegistrations;
import touchline.transport.gamecontroller.BadPackets;
import touchline.transport.gamecontroller.GcListener;

import touchline.app.game.GameControllerSources;
import touchline.app.game.MatchMode;
import touchline.protocol.gamecontroller.Decoded;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * Listens to the game-state port (3838) when the console does not run the GameController
 * itself, e.g. at a tournament: every game-state packet (any known format, HL v12 to HSL v20,
 * and the HSL monitors' true data) becomes an IN envelope, and its state feeds
 * {@link MatchMode}, so the console falls silent while the official GameController says READY,
 * SET or PLAYING. A packet no format accepts, or true data from a GameController this console
 * did not register with, is published with its reason and counted in {@link #badPackets()},
 * never thrown and never believed; the next good one is used as usual. The field's GameController
 * is pinned ({@link GameControllerSources}): game states from any other source are published
 * with the reason they are not believed and counted the same way, yet still heard by match
 * mode, where a claim of play from anyone keeps the console silent.
 */
public final class GameStateWatch implements AutoCloseable {

    private final KnownGameStateFormats formats = new KnownGameStateFormats();
    private final BadPackets badPackets = new BadPackets();
    private final EnvelopeSink sink;
    private final MatchMode matchMode;
    private final MonitorRegistrations registrations;
    private final GameControllerSources sources;
    private final GcListener listener;
    /** Envelope time stamps (the console's wall clock). */
    private final MicrosClock stamps;

    /**
     * @param bind      usually 0.0.0.0:3838 (shared with SO_REUSEADDR)
     * @param sink      receives one GAMECONTROLLER envelope per game-state datagram
     * @param matchMode told each decoded state
     * @param clock     the console's monotonic clock (the pinned GameController's silence)
     * @param stamps    the console's wall clock, for the envelopes' time stamps
     */
    public GameStateWatch(InetSocketAddress bind, EnvelopeSink sink, MatchMode matchMode, touchline.game.GameClock clock,
                          MicrosClock stamps) throws IOException {
        this(bind, sink, matchMode, new MonitorRegistrations(), new GameControllerSources(clock, null), stamps);
    }

    /** @param registrations the GameControllers whose true data ("RGTD") this console asked for */
    public GameStateWatch(InetSocketAddress bind, EnvelopeSink sink, MatchMode matchMode,
                          MonitorRegistrations registrations, touchline.game.GameClock clock, MicrosClock stamps)
            throws IOException {
        this(bind, sink, matchMode, registrations, new GameControllerSources(clock, null), stamps);
    }

    /**
     * @param registrations the GameControllers whose true data ("RGTD") this console asked for
     * @param sources       pins the field's GameController and judges every game state heard
     * @param stamps        the console's wall clock, for the envelopes' time stamps
     */
    public GameStateWatch(InetSocketAddress bind, EnvelopeSink sink, MatchMode matchMode,
                          MonitorRegistrations registrations, GameControllerSources sources, MicrosClock stamps)
            throws IOException {
        this.sources = sources;
        this.stamps = stamps;
        this.sink = sink;
        this.matchMode = matchMode;
        this.registrations = registrations;
        this.listener = new GcListener(bind, this::onDatagram, "gc-watch");
    }

    /** Rejected game-state packets, per source with the last reason. */
    public BadPackets badPackets() {
        return badPackets;
    }

    /** The pinned GameController, intruders and flags. */
    public GameControllerSources sources() {
        return sources;
    }

    public InetSocketAddress localAddress() throws IOException {
        return listener.localAddress();
    }

    private void onDatagram(byte[] data, InetSocketAddress from) {
        if (!KnownGameStateFormats.isGameState(data)) {
            return; // robots' own broadcasts on the shared port are somebody else's business
        }
        Decoded<KnownGameStateFormats.Match> r = formats.recognise(data);
        KnownGameStateFormats.Match m = r.value();
        String error = m == null ? r.failure() + ": " + r.detail()
                : m.format().isTrueData() && !registrations.isRegisteredWith(from.getAddress())
                ? "monitor true data (RGTD) from " + from.getAddress().getHostAddress()
                  + ", but this console did not register as its monitor" : null;
        String host = from.getAddress().getHostAddress();
        boolean intruder = error == null
                && sources.heard(host, from.getPort(), m.data()) == GameControllerSources.Verdict.INTRUDER;
        if (intruder) {
            error = "game state from " + host + ":" + from.getPort() + ", not the field's GameController ("
                    + sources.pinnedHost() + "): not believed";
        }
        if (error != null) {
            badPackets.count(from, error);
        }
        sink.accept(new Envelope(stamps.nowMicros(), Direction.IN, Channel.GAMECONTROLLER, from, Envelope.NO_ROBOT,
                m == null ? "gc.unknown" : m.format().kind(), null, data, error));
        if (m != null && (error == null || intruder)) {
            // the strictest claim wins: an intruder saying PLAYING silences the console too (but
            // its INITIAL does not end the first listen)
            if (intruder) {
                matchMode.observe(m.data().state(), "other source at " + host + ":" + from.getPort());
            } else {
                matchMode.observeBelieved(m.data().state(), "GameController at " + host + ":" + from.getPort());
            }
        }
    }

    @Override
    public void close() {
        listener.close();
    }
}
