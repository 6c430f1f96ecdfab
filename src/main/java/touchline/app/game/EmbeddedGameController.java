package touchline.app.game;

import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcSender;
import touchline.transport.gamecontroller.MonitorService;
import touchline.transport.gamecontroller.MonitorStats;
import touchline.transport.gamecontroller.BadPackets;
import touchline.transport.gamecontroller.GcProfile;
import touchline.transport.gamecontroller.RobotLiveness;
import touchline.transport.gamecontroller.GcListener;
import touchline.transport.gamecontroller.MonitorRegistrations;

import touchline.game.Game;
import touchline.game.RefereedGame;
import touchline.protocol.gamecontroller.KnownGameStateFormats;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.GameState7;
import touchline.protocol.gamecontroller.GameStateFormat;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.NetworkInterface;
import java.net.SocketException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * The GameController running inside the console: a refereed game owned by its
 * {@link GameRuntime} (thread {@value GameRuntime#THREAD}) and published by a {@link GcSender}
 * that reads the owner's snapshots; return packets received and turned into liveness and
 * (edge-triggered) manual penalties, enqueued to the owner; other GameControllers heard on the
 * game-state port through its one listener ({@link GameStateWatch}: the console's, or one of its
 * own for {@code gc}) and kept as rivals by {@link GameControllerStates}, which also tells match
 * mode the state we send. Every datagram in or out is published as a GAMECONTROLLER envelope;
 * our own packets heard back on a shared port are recognised by source and ignored. Bad return
 * packets are counted per source and never applied. Notable events (rival heard, first bad
 * packet of a source, robot requests) go to event listeners as text.
 */
public final class EmbeddedGameController implements AutoCloseable {


    /** The HL game when one is refereed (robots' manual penalty requests apply to it), else null. */
    private final Game game;
    /** The only thread that changes the game; everything here enqueues to it or reads its snapshot. */
    private final GameRuntime runtime;
    private final GcConfig config;
    private final EnvelopeSink sink;
    /** The one source of GameController states for match mode; its tracker keeps our rivals. */
    private final GameControllerStates states;
    private final Own own = new Own();
    /** Where rivals are heard: the console's one listener on the game-state port, or our own; null: nowhere. */
    private GameStateWatch watch;
    private final boolean ownsWatch;
    /** Return packets arrive through {@link #watch} (they share its port). */
    private boolean returnsOnWatch;
    /** Our own return-packet listener, unless they come through the watch. */
    private GcListener returns;
    /** Envelope time stamps (the console's wall clock). */
    private final MicrosClock stamps;
    private final BadPackets badPackets = new BadPackets();
    private final ReturnPackets returnPackets;
    private final List<Consumer<String>> eventListeners = new CopyOnWriteArrayList<>();
    private final GcSender sender;
    private volatile MonitorService monitors;
    private final int senderPort;

    /**
     * @param game      the game to referee
     * @param config    formats, addresses and ports
     * @param sink      receives every GameController envelope (IN and OUT)
     * @param matchMode told the state we send and the states we hear (may be null)
     * @param stamps    the console's wall clock, for the envelopes' time stamps
     */
    public EmbeddedGameController(Game game, GcConfig config, EnvelopeSink sink, MatchMode matchMode,
                                  MicrosClock stamps) throws IOException {
        this((RefereedGame) game, config, sink, matchMode, stamps);
    }

    /**
     * @param referee   the game to referee: an HSL game for the HSL formats, an HL {@link Game}
     *                  for the others
     * @param config    formats, addresses and ports
     * @param sink      receives every GameController envelope (IN and OUT)
     * @param matchMode told the state we send and the states we hear (may be null)
     * @param stamps    the console's wall clock, for the envelopes' time stamps
     * @throws IllegalArgumentException when the game's rules do not fit the format
     */
    public EmbeddedGameController(RefereedGame referee, GcConfig config, EnvelopeSink sink, MatchMode matchMode,
                                  MicrosClock stamps) throws IOException {
        this(referee, config, sink, null, matchMode, stamps);
    }

    /**
     * A GameController inside a console that already listens on the game-state port: it hears its
     * rivals (and, where they share that port, its return packets) through {@code watch}, the one
     * listener there, and tells match mode through the watch's {@link GameControllerStates};
     * {@code config.rivalBind()} is not opened a second time.
     */
    public EmbeddedGameController(RefereedGame referee, GcConfig config, GameStateWatch watch, EnvelopeSink sink,
                                  MicrosClock stamps) throws IOException {
        this(referee, config, sink, watch, null, stamps);
    }

    private EmbeddedGameController(RefereedGame referee, GcConfig config, EnvelopeSink sink, GameStateWatch shared,
                                   MatchMode matchMode, MicrosClock stamps) throws IOException {
        boolean hslGame = !(referee instanceof Game);
        if (hslGame != config.profile().hsl()) {
            throw new IllegalArgumentException(config.profile().hsl()
                    ? "the " + config.profile().cliName() + " format sends a game under the HSL 2026 rules; "
                    + "referee it with 'touchline gc --format " + config.profile().cliName() + "'"
                    : "an HSL game is sent in the hsl20 or hsl19 format, not " + config.profile().cliName());
        }
        this.game = referee instanceof Game g ? g : null;
        this.runtime = new GameRuntime(referee);
        this.config = config;
        this.sink = sink;
        this.stamps = stamps;
        this.returnPackets = new ReturnPackets(game, runtime, sink, stamps, badPackets, () -> monitors, this::emit);
        this.states = shared != null ? shared.states() : new GameControllerStates(sink, matchMode,
                new MonitorRegistrations(), new GameControllerSources(referee::now, null), badPackets, stamps);
        List<GameStateFormat> formats = new ArrayList<>();
        formats.add(config.profile().format());
        if (config.v7Compat() && config.profile() != GcProfile.V7) {
            formats.add(new GameState7());
        }
        sender = new GcSender(new RobotsCycle(), formats, config.destinations(), config.senderBind(), sink,
                config.intervalMs(), config.profile().hsl(), stamps);
        senderPort = sender.localAddress().getPort();
        sender.useRealtimePriority(config.realtime());
        this.ownsWatch = shared == null;
        try {
            watch = shared != null ? shared
                    : config.rivalBind() != null ? new GameStateWatch(config.rivalBind(), states) : null;
            // one listener per port: returns that share the game-state port come through the watch
            returnsOnWatch = watch != null && watch.localAddress().getPort() == config.returnBind().getPort();
            if (!returnsOnWatch) {
                returns = new GcListener(config.returnBind(), this::onReturnPortDatagram, "gc-returns");
            }
        } catch (IOException e) {
            close();
            throw e;
        }
        runtime.addListener(s -> sender.changed(s.robots().stopped()));
    }

    /**
     * Starts the game's owner, its listeners (return packets; its own 3838 watch, if it made one),
     * then the sender; from now on other GameControllers heard are rivals.
     */
    public void start() {
        states.referee(own);
        runtime.start();
        if (returns != null) {
            returns.start();
        }
        if (ownsWatch && watch != null) {
            watch.start();
        }
        sender.start();
    }

    /**
     * Answers monitor applications as the official HSL GameController does (HSL formats only;
     * {@link MonitorService}): requests on {@code requestBind}, true data to the monitors'
     * {@code trueDataPort}, return packets forwarded to their {@code forwardPort}.
     */
    public MonitorService serveMonitors(InetSocketAddress requestBind, int trueDataPort, int forwardPort)
            throws IOException {
        if (!config.profile().hsl()) {
            throw new IllegalStateException("monitors are served in the HSL formats only");
        }
        MonitorService m = new MonitorService(requestBind, trueDataPort, forwardPort,
                config.profile().trueDataFormat(), this::emit, stamps);
        m.start();
        monitors = m;
        return m;
    }

    /**
     * Where monitors send their requests, once {@link #serveMonitors} ran (the faces show it);
     * null before.
     */
    public InetSocketAddress monitorRequestAddress() throws IOException {
        MonitorService m = monitors;
        return m == null ? null : m.requestAddress();
    }

    /** What the monitor service did so far; null before {@link #serveMonitors} ran. */
    public MonitorStats monitorStats() {
        MonitorService m = monitors;
        return m == null ? null : m.stats();
    }

    /**
     * The owner of the game refereed here: every change goes to it as an event; views and
     * commands read its snapshot.
     */
    public GameRuntime runtime() {
        return runtime;
    }

    /** Whether the game refereed here follows the HSL rules. */
    public boolean hsl() {
        return game == null;
    }

    public GcConfig config() {
        return config;
    }

    public RobotLiveness liveness() {
        return returnPackets.liveness();
    }

    public BadPackets badPackets() {
        return badPackets;
    }

    /** Other GameControllers heard while this one referees (the one tracker, {@link GameControllerSources#others()}). */
    public RivalGameControllers rivals() {
        return states.sources().others();
    }

    public GcSender sender() {
        return sender;
    }

    /** Game-state packets sent so far (every format counted). */
    public long packetsSent() {
        return sender.packetsSent();
    }

    /** Packets the socket refused so far. */
    public long sendErrors() {
        return sender.sendErrors();
    }

    /** What became of the real-time priority asked for the sender, in words (see {@link GcSender}). */
    public String realtimeOutcome() {
        return sender.realtimeOutcome();
    }

    /** {@link #realtimeOutcome()} as a value the faces switch on. */
    public SenderPriority senderPriority() {
        return SenderPriority.of(sender.realtimeOutcome());
    }

    /** {@link #realtimeOutcome()} once the sender's thread has tried (at most {@code timeoutMs}). */
    public String awaitRealtimeOutcome(long timeoutMs) {
        return sender.awaitRealtimeOutcome(timeoutMs);
    }

    /** Sends the current state now, out of schedule (a change the referee just made). */
    public void sendNow() {
        sender.sendNow();
    }

    /** The bound return-packet address (useful when port 0 was configured). */
    public InetSocketAddress returnAddress() throws IOException {
        return returnsOnWatch ? watch.localAddress() : returns.localAddress();
    }

    /** Where rivals are heard (the game-state port's one listener), or null when nowhere. */
    public InetSocketAddress rivalAddress() throws IOException {
        return watch == null ? null : watch.localAddress();
    }

    public void addEventListener(Consumer<String> onEvent) {
        eventListeners.add(onEvent);
    }

    /** "" or the loud warning that another GameController is sending. */
    public String rivalWarning() {
        return rivals().warning(states.sources().now());
    }

    /**
     * The robots' send cycle: the state to send, and after the robots' datagrams went out, the
     * true state handed to the monitors (whose thread sends it), so no monitor delays the robots.
     * It changes nothing and never waits for the owner: a periodic cycle sends the newest
     * snapshot with time run on to its instant ({@link GameRuntime#timed()}, which also enqueues
     * the owner's timer event); a send after a change sends the snapshot of that change.
     */
    private final class RobotsCycle implements GcSender.Source {

        /** The true state of the last periodic cycle, until it is handed over (sender thread only). */
        private GameControlData truth;

        @Override
        public GameControlData next(boolean periodic) {
            RefereeSnapshot s = periodic ? runtime.timed() : runtime.snapshot();
            GameControlData data = s.robots();
            if (periodic && monitors != null) {
                truth = s.truth();
            }
            states.own(data.state());
            return data;
        }

        @Override
        public void sent(boolean periodic) {
            MonitorService m = monitors;
            if (periodic && m != null && truth != null) {
                m.publish(truth);
            }
            truth = null;
        }
    }

    /** This GameController as the one source of states knows it while it referees. */
    private final class Own implements GameControllerStates.Referee {

        @Override
        public boolean ownPacket(InetSocketAddress from) {
            return from.getPort() == senderPort && isLocal(from.getAddress());
        }

        @Override
        public void rivalHeard(String warning) {
            emit(warning);
        }

        @Override
        public void otherDatagram(byte[] data, InetSocketAddress from) {
            if (returnsOnWatch) {
                returnPackets.accept(data, from);
            }
        }
    }

    private void onReturnPortDatagram(byte[] data, InetSocketAddress from) {
        if (KnownGameStateFormats.isGameState(data)) {
            states.datagram(data, from); // a rival, or our own heard back, where the ports are shared
            return;
        }
        returnPackets.accept(data, from);
    }

    private static boolean isLocal(InetAddress a) {
        if (a.isLoopbackAddress() || a.isAnyLocalAddress()) {
            return true;
        }
        try {
            return NetworkInterface.getByInetAddress(a) != null;
        } catch (SocketException e) {
            return false;
        }
    }

    private void emit(String event) {
        for (Consumer<String> l : eventListeners) {
            l.accept(event);
        }
    }

    @Override
    public void close() {
        states.endRefereeing(own);
        sender.close();
        runtime.close();
        MonitorService m = monitors;
        if (m != null) {
            m.close();
        }
        if (returns != null) {
            returns.close();
        }
        if (ownsWatch && watch != null) {
            watch.close();
        }
    }
}
