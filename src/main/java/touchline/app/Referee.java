package touchline.app;

import touchline.app.game.EmbeddedGameController;
import touchline.app.game.GameControllerSources;
import touchline.app.game.GameStateWatch;
import touchline.app.game.MatchMode;
import touchline.app.game.MonitorReport;
import touchline.game.GameClock;
import touchline.game.RefereedGame;
import touchline.transport.EnvelopeSink;
import touchline.transport.MicrosClock;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcMonitor;
import touchline.transport.gamecontroller.MonitorRegistrations;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.time.Duration;
import java.util.Optional;
import java.util.function.BooleanSupplier;

/**
 * The referee's side of the console: match mode, the GameControllers heard on 3838 and the one
 * believed, this console as the field's HSL GameController's monitor, and the embedded
 * GameController a user referees a game with (one at a time). The {@code gc} command uses one
 * without a console ({@link #Referee(EnvelopeSink, MatchMode, SystemClock)}).
 */
public final class Referee {

    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(Referee.class);

    private final ConsoleConfig config;
    private final EnvelopeSink live;
    private final MatchMode matchMode;
    private final MicrosClock clock;
    private final GameClock gameClock;
    private final GameControllerSources sources;
    private final BooleanSupplier commandsOff;
    private final MonitorRegistrations monitorRegistrations = new MonitorRegistrations();
    private GameStateWatch watch;
    private GcMonitor monitor;
    /** When the GameController port was opened (the console's clock), for {@link #awaitFirstListen}. */
    private volatile long listeningSinceMicros;
    /** Read without the lock: a frame asking for it never waits for a start or stop in progress. */
    private volatile EmbeddedGameController gameController;
    /** The close {@link #stopInBackground} runs; done when nothing is closing. */
    private java.util.concurrent.CompletableFuture<Void> closing = java.util.concurrent.CompletableFuture.completedFuture(null);

    Referee(ConsoleConfig config, EnvelopeSink live, MatchMode matchMode, MicrosClock clock, SystemClock realClock,
            BooleanSupplier commandsOff) {
        this.config = config;
        this.live = live;
        this.matchMode = matchMode;
        this.clock = clock;
        this.gameClock = realClock;
        this.sources = new GameControllerSources(realClock, pinnedGameController(config));
        this.commandsOff = commandsOff;
    }

    /**
     * A referee without a console (the {@code gc} command): its GameController's packets go to
     * {@code live}, what it sends to {@code matchMode}; nothing is heard on 3838.
     */
    public Referee(EnvelopeSink live, MatchMode matchMode, SystemClock clock) {
        this(ConsoleConfig.defaults().withGameControllerPort(0), live, matchMode, clock, clock, () -> false);
    }

    /**
     * Listens on the GameController port (3838, shared with SO_REUSEADDR) so match mode hears
     * the referee box, and registers as the field's HSL GameController's monitor when asked
     * ({@code --gc-monitor}); a port that cannot be opened is reported and the console runs on.
     */
    void listen() {
        watchGameController();
        monitorGameController();
    }

    private void watchGameController() {
        if (config.gameControllerPort() <= 0) {
            return;
        }
        try {
            watch = new GameStateWatch(new InetSocketAddress(config.udp().bindAddress(), config.gameControllerPort()),
                    live, matchMode, monitorRegistrations, sources, clock).start();
            // started in the middle of a game, the console must hear the GameController before it talks
            listeningSinceMicros = clock.nowMicros();
            matchMode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        } catch (IOException e) {
            LOG.warn("cannot listen for GameControllers on port {}: {} "
                    + "(match mode still follows the robots' reported game state)", config.gameControllerPort(), e.toString());
        }
    }

    /**
     * Its true state then drives match mode and its forwarded return packets show each robot as
     * the referee sees it.
     */
    private void monitorGameController() {
        if (config.gcMonitor() == null) {
            return;
        }
        try {
            monitor = new GcMonitor(config.gcMonitor(), new InetSocketAddress(config.udp().bindAddress(),
                    config.gcForwardPort()), monitorRegistrations, live, clock).start();
        } catch (IOException e) {
            LOG.warn("cannot monitor the GameController at {}: {}", config.gcMonitor(), e.toString());
        }
    }

    /** The GameController host to believe: the one given, else the monitored one, else null (the first heard). */
    private static String pinnedGameController(ConsoleConfig config) {
        if (config.gcAddress() != null) {
            InetAddress a;
            try {
                a = InetAddress.getByName(config.gcAddress());
            } catch (UnknownHostException e) {
                LOG.warn("--gc-address {}: unknown host; believing no GameController until it resolves",
                        config.gcAddress());
                return config.gcAddress();
            }
            return a.getHostAddress();
        }
        return config.gcMonitor() == null || config.gcMonitor().getAddress() == null ? null
                : config.gcMonitor().getAddress().getHostAddress();
    }

    /**
     * A one-shot command's wait before its first request (`touchline options`, `touchline nao`): a
     * console that just opened the GameController port listens for one first, and match mode holds
     * robot traffic meanwhile. Returns once that first listen is over and the port has been open
     * for at least {@code listenMillis} (longer on a lossy network); at once when play is heard
     * (match mode then holds the request and says why) or no GameController port is open; at the
     * latest after {@code timeout} (on the console's clock).
     */
    public void awaitFirstListen(long listenMillis, Duration timeout) throws InterruptedException {
        if (watch == null) {
            return;
        }
        long until = listeningSinceMicros + listenMillis * 1000;
        long end = clock.nowMicros() + timeout.toNanos() / 1000;
        while (clock.nowMicros() < end && !matchMode.playIsOn()
                && (matchMode.listeningFirst() || clock.nowMicros() < until)) {
            Thread.sleep(10);
        }
    }

    public MatchMode matchMode() { return matchMode; }

    /** Monotonic milliseconds for a game a face sets up ({@link #start}). */
    public GameClock gameClock() { return gameClock; }

    /**
     * Which GameController the console believes (pinned: the first heard, or {@code --gc-address}),
     * the other sources sending game states, and what looked wrong (docs/security.md).
     */
    public GameControllerSources sources() {
        return sources;
    }

    /** The monitor of the field's GameController, or null when not asked for (or its port was taken). */
    public GcMonitor monitor() {
        return monitor;
    }

    /**
     * The robots as the field's GameController sees them at {@code nowMs} (wall time, ms), when
     * this console is its monitor; empty otherwise.
     */
    public Optional<MonitorReport> monitorReport(long nowMs) {
        GcMonitor m = monitor;
        return m == null ? Optional.empty() : Optional.of(new MonitorReport(m.robots().size(), m.describe(nowMs)));
    }

    /** What a face does to an embedded GameController before it starts sending (listeners, monitors' port). */
    @FunctionalInterface
    public interface SetUp {
        void prepare(EmbeddedGameController gc) throws IOException;
    }

    /**
     * Starts refereeing a game of any rules: the embedded GameController sends {@code game}'s state
     * to {@code gcConfig}'s destinations, publishes its packets into the Envelope stream and tells
     * match mode what it sends. An {@link touchline.game.hsl.HslGame} goes in the HSL formats, an
     * HL {@link touchline.game.Game} in the others (a mismatch is refused with the reason). One at
     * a time; a running one is stopped first.
     */
    public EmbeddedGameController start(RefereedGame game, GcConfig gcConfig) throws IOException {
        return start(game, gcConfig, gc -> { });
    }

    /** As {@link #start(RefereedGame, GcConfig)}, with {@code setUp} done before the first packet. */
    public synchronized EmbeddedGameController start(RefereedGame game, GcConfig gcConfig, SetUp setUp)
            throws IOException {
        if (commandsOff.getAsBoolean()) {
            throw new IOException(RemoteView.COMMANDS_OFF);
        }
        stop();
        EmbeddedGameController gc = watch != null ? new EmbeddedGameController(game, gcConfig, watch, live, clock)
                : new EmbeddedGameController(game, gcConfig, live, matchMode, clock); // one listener on 3838
        try {
            setUp.prepare(gc);
            gc.start();
        } catch (RuntimeException | IOException e) {
            gc.close();
            throw e instanceof IOException io ? io : new IOException(e.getMessage(), e);
        }
        gameController = gc;
        return gc;
    }

    /**
     * Starts as {@link #start(RefereedGame, GcConfig, SetUp)} without waiting (the window's Start,
     * on the FX thread): the stop of a running one, the sockets and the threads are done on a
     * {@code gc-start} thread; the future completes with the running GameController, or with
     * why it did not start.
     */
    public java.util.concurrent.CompletableFuture<EmbeddedGameController> startInBackground(RefereedGame game,
            GcConfig gcConfig, SetUp setUp) {
        java.util.concurrent.CompletableFuture<EmbeddedGameController> done = new java.util.concurrent.CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                done.complete(start(game, gcConfig, setUp));
            } catch (IOException | RuntimeException e) {
                done.completeExceptionally(e);
            }
        }, "gc-start");
        t.setDaemon(true);
        t.start();
        return done;
    }

    public Optional<EmbeddedGameController> gameController() {
        return Optional.ofNullable(gameController);
    }

    /** Stops the running GameController and waits for it (and for one stopping in the background). */
    public synchronized void stop() {
        if (gameController != null) {
            gameController.close();
            gameController = null;
        }
        closing.join();
    }

    /**
     * Stops the running GameController without waiting (the window's Stop, on the FX thread): it
     * is no longer the running one at once, its close (which joins {@code gc-game}) runs on a
     * {@code gc-stop} thread; the future completes when it is closed.
     */
    public synchronized java.util.concurrent.CompletableFuture<Void> stopInBackground() {
        EmbeddedGameController gc = gameController;
        if (gc == null) {
            return closing;
        }
        gameController = null;
        java.util.concurrent.CompletableFuture<Void> done = new java.util.concurrent.CompletableFuture<>();
        Thread t = new Thread(() -> {
            try {
                gc.close();
                done.complete(null);
            } catch (RuntimeException e) {
                LOG.warn("stopping the GameController failed: {}", e.toString());
                done.completeExceptionally(e);
            }
        }, "gc-stop");
        t.setDaemon(true);
        closing = done;
        t.start();
        return done;
    }

    /** A claim of play expires with time: held requests go out then. */
    void tick() {
        matchMode.refresh();
    }

    void close() {
        stop();
        if (watch != null) {
            watch.close();
        }
        if (monitor != null) {
            monitor.close();
        }
    }
}
