package touchline.app.game;

import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.gamecontroller.BadPackets;
import touchline.transport.gamecontroller.GcListener;
import touchline.transport.gamecontroller.MonitorRegistrations;

import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * The one listener on the game-state port (3838): every datagram heard there goes to
 * {@link GameControllerStates}, the one source of GameController states for {@link MatchMode},
 * which judges it (any known format, HL v12 to HSL v20, and the HSL monitors' true data), pins the
 * field's GameController, publishes each game state as an IN envelope and counts what it refuses
 * in {@link #badPackets()}, never thrown and never believed. While this console referees, the same
 * listener hears the rivals of its GameController (and, on the 2014 profiles, its return packets).
 * The port is bound when made; it listens from {@link #start()}.
 */
public final class GameStateWatch implements AutoCloseable {

    private final GameControllerStates states;
    private final GcListener listener;

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
        this(bind, new GameControllerStates(sink, matchMode, registrations, sources, new BadPackets(), stamps));
    }

    /** Listens on {@code bind} for {@code states}. */
    public GameStateWatch(InetSocketAddress bind, GameControllerStates states) throws IOException {
        this.states = states;
        this.listener = new GcListener(bind, states::datagram, "gc-watch");
    }

    /** Starts listening (the thread that hands each datagram to the states); returns this. */
    public GameStateWatch start() {
        listener.start();
        return this;
    }

    /** What this listener feeds: the one source of GameController states. */
    public GameControllerStates states() {
        return states;
    }

    /** Rejected game-state packets, per source with the last reason. */
    public BadPackets badPackets() {
        return states.badPackets();
    }

    /** The pinned GameController, intruders and flags. */
    public GameControllerSources sources() {
        return states.sources();
    }

    public InetSocketAddress localAddress() throws IOException {
        return listener.localAddress();
    }

    @Override
    public void close() {
        listener.close();
    }
}
