package touchline.app;

import touchline.game.GameClock;
import touchline.app.game.GameControllerSources;
import touchline.app.game.MatchMode;
import touchline.app.game.MatchModeJson;
import touchline.model.DebugOptionSession;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.game.Game;
import touchline.game.RefereedGame;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.GameStateWatch;
import touchline.transport.gamecontroller.GcMonitor;
import touchline.transport.gamecontroller.MonitorRegistrations;
import touchline.transport.gamecontroller.GcConfig;
import java.net.InetSocketAddress;
import touchline.model.RobotRegistry;
import touchline.model.DebugRateGuard;
import touchline.model.RuleProfile;
import touchline.model.TeamMessageBudget;
import touchline.model.TrafficMeter;
import touchline.transport.TeamMessageListener;
import touchline.model.store.NetworkLog;
import touchline.model.store.PlotStore;
import touchline.model.store.TextLog;
import touchline.protocol.MessageCodec;
import touchline.protocol.MessageKinds;
import touchline.transport.EnvelopeBus;
import touchline.transport.MicrosClock;
import touchline.transport.ReliableStreamHandler;
import touchline.transport.SendGate;
import touchline.transport.SendResult;
import touchline.transport.UdpTransport;
import touchline.transport.ReliableSession;
import touchline.model.RobotSnapshot;

import touchline.record.EnvelopeWriter;
import touchline.record.Recorder;
import touchline.record.RecorderStats;
import touchline.record.ReplaySession;
import touchline.record.RecordingException;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The application core both faces share: the Envelope stream, the UDP transport feeding it,
 * and the model listening to it. The UI and the CLI construct one Console and read from its
 * model; anything they do to data goes through here.
 */
public final class Console implements AutoCloseable {

    private final ConsoleConfig config;
    private final MicrosClock clock;
    private final MicrosClock modelClock;
    private final MicrosClock replayClock;
    private final MessageKinds kinds = new MessageKinds();
    private final MessageCodec codec = new MessageCodec(kinds);
    private final TeamSchemas teamSchemas = new TeamSchemas(kinds);
    private final EnvelopeBus bus = new EnvelopeBus();
    private final LiveSwitch live = new LiveSwitch(bus);
    private Recorder recorder;
    private AutoCloseable recorderSubscription;
    private volatile Replay replay;
    private final RobotRegistry robots;
    private final TrafficMeter traffic;
    private final DebugOptionSession options;
    private final UdpTransport udp;
    private final ReliableStreamHandler reliable;
    private final ScheduledExecutorService ticker;
    /** The real clock's monotonic faces (match mode, the game, replay pacing); stateless, like every SystemClock. */
    private final SystemClock realClock = new SystemClock();
    private final MatchMode matchMode = new MatchMode(realClock);
    private GameStateWatch gcWatch;
    /** When the GameController port was opened (the console's clock), for {@link #awaitFirstListen}. */
    private volatile long listeningSinceMicros;
    private final GameControllerSources gcSources;
    private final MonitorRegistrations monitorRegistrations = new MonitorRegistrations();
    private GcMonitor gcMonitor;
    private EmbeddedGameController gameController;
    private TeamMessageListener teamMessages;
    /** Team messages heard since the console started, for the counts in (read without the console's lock). */
    private final java.util.concurrent.atomic.AtomicLong teamDatagramsIn = new java.util.concurrent.atomic.AtomicLong();
    private final java.util.concurrent.atomic.AtomicLong teamBytesIn = new java.util.concurrent.atomic.AtomicLong();
    private AutoCloseable budgetSubscription;
    private TeamMessageBudget budget;
    private DebugRateGuard debugRate;
    private AutoCloseable debugRateSubscription;
    private final touchline.model.store.ViewStores stores;
    private volatile touchline.transport.remote.RemoteStream remote;

    /** Why a console viewing another Touchline's stream sends nothing: every command path says this. */
    public static final String COMMANDS_OFF = "viewing a remote Touchline: commands are off";
    private volatile WantedOptionsFile wantedFile;
    /** What the match-mode gate adds for debug requests, which are asked again after play; a NAO call is not. */
    private static final String SENT_LATER = "; goes out when play stops";
    private volatile SendGate gate = SendGate.open();
    private final List<NaoSession> naos = new java.util.concurrent.CopyOnWriteArrayList<>();
    private final List<NaoCamera> naoCameras = new java.util.concurrent.CopyOnWriteArrayList<>();
    private final NaoCameraFeed naoCamera;
    private final NaoCallFeed naoCalls;
    private final RobotWaits robotWaits;
    private final touchline.app.bridges.RosBridges bridges;

    public Console(ConsoleConfig config) {
        this(config, new SystemClock());
    }

    public Console(ConsoleConfig config, MicrosClock clock) {
        this(config, clock, true);
    }

    /** @param withModel false leaves the model unsubscribed (benchmarks of the bare transport) */
    public Console(ConsoleConfig config, MicrosClock clock, boolean withModel) {
        this.config = config;
        this.clock = clock;
        this.gcSources = new GameControllerSources(realClock, pinnedGameController(config));
        // The traffic meter's "now" follows a replay while one plays with live listening paused,
        // so its rates are the recording's rates.
        modelClock = () -> {
            Replay r = replay;
            return r != null && !live.isLive() ? r.state().positionMicros() : clock.nowMicros();
        };
        // Replayed robots are online, and their options stream, by the replay's position;
        // live robots by the wall clock, whatever a replay does.
        replayClock = () -> {
            Replay r = replay;
            return r != null ? r.state().positionMicros() : clock.nowMicros();
        };
        this.robots = new RobotRegistry(clock, replayClock, RobotRegistry.DEFAULT_OFFLINE_AFTER_MICROS);
        this.naoCamera = new NaoCameraFeed(clock, replayClock, () -> replay != null);
        this.naoCalls = new NaoCallFeed(() -> replay != null);
        this.robotWaits = new RobotWaits(clock);
        this.traffic = new TrafficMeter(modelClock);
        this.reliable = new ReliableStreamHandler(live, clock);
        this.udp = new UdpTransport(config.udp(), config.security(), codec, live, clock, reliable);
        reliable.useAuth(udp.segmentAuth());
        this.options = new DebugOptionSession(udp, codec, clock, replayClock);
        this.stores = new touchline.model.store.ViewStores(TextLog.DEFAULT_CAPACITY, PlotStore.DEFAULT_POINTS,
                NetworkLog.DEFAULT_CAPACITY, clock.nowMicros(), () -> replay != null);
        bus.subscribe(new ReportedGameState(matchMode));
        this.bridges = new touchline.app.bridges.RosBridges(live, robots, stores, matchMode, clock,
                () -> gate.holdReason(), COMMANDS_OFF);
        bus.subscribe(bridges);
        setGate(() -> matchMode.hold("console request")
                ? Optional.of("match mode, " + matchMode.play() + SENT_LATER) : Optional.empty());
        if (withModel) {
            bus.subscribe(robots);
            bus.subscribe(traffic);
            bus.subscribe(options);
            bus.subscribe(stores);
            bus.subscribe(naoCamera);
            bus.subscribe(naoCalls);
            robots.addPresenceListener(options);
            robots.addPresenceListener(robotWaits);
        }
        this.ticker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "touchline-tick");
            t.setDaemon(true);
            return t;
        });
    }

    /** Binds the UDP port and starts the model's clock; returns this for chaining. */
    public Console start() throws InterruptedException {
        udp.start();
        watchGameController();
        monitorGameController();
        ticker.scheduleAtFixedRate(this::tick, config.tickMillis(), config.tickMillis(), TimeUnit.MILLISECONDS);
        return this;
    }

    /**
     * A one-shot command's wait before its first request (`touchline options`, `touchline nao`): a
     * console that just opened the GameController port listens for one first, and match mode holds
     * robot traffic meanwhile. Returns once that first listen is over and the port has been open
     * for at least {@code listenMillis} (longer on a lossy network); at once when play is heard
     * (match mode then holds the request and says why) or no GameController port is open; at the
     * latest after {@code timeout} (on the console's clock).
     */
    public void awaitFirstListen(long listenMillis, java.time.Duration timeout) throws InterruptedException {
        if (gcWatch == null) {
            return;
        }
        long until = listeningSinceMicros + listenMillis * 1000;
        long end = clock.nowMicros() + timeout.toNanos() / 1000;
        while (clock.nowMicros() < end && !matchMode.playIsOn()
                && (matchMode.listeningFirst() || clock.nowMicros() < until)) {
            Thread.sleep(10);
        }
    }

    /**
     * Listens on the GameController port (3838, shared with SO_REUSEADDR) so match mode hears
     * the referee box; a port that cannot be opened is reported and the console runs on.
     */
    private void watchGameController() {
        if (config.gameControllerPort() <= 0) {
            return;
        }
        try {
            gcWatch = new GameStateWatch(new InetSocketAddress(config.udp().bindAddress(), config.gameControllerPort()),
                    live, matchMode, monitorRegistrations, gcSources, clock);
            // started in the middle of a game, the console must hear the GameController before it talks
            listeningSinceMicros = clock.nowMicros();
            matchMode.listenFirst(MatchMode.LISTEN_FIRST_MS);
        } catch (IOException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("cannot listen for GameControllers on port {}: {} "
                    + "(match mode still follows the robots' reported game state)", config.gameControllerPort(), e.toString());
        }
    }

    /**
     * Registers with the field's HSL GameController as a monitor when asked ({@code --gc-monitor}):
     * its true state then drives match mode and its forwarded return packets show each robot
     * as the referee sees it. A port that cannot be opened is reported and the console runs on.
     */
    private void monitorGameController() {
        if (config.gcMonitor() == null) {
            return;
        }
        try {
            gcMonitor = new GcMonitor(config.gcMonitor(), new InetSocketAddress(config.udp().bindAddress(),
                    config.gcForwardPort()), monitorRegistrations, live, clock);
        } catch (IOException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("cannot monitor the GameController at {}: {}",
                    config.gcMonitor(), e.toString());
        }
    }

    /** The GameController host to believe: the one given, else the monitored one, else null (the first heard). */
    private static String pinnedGameController(ConsoleConfig config) {
        if (config.gcAddress() != null) {
            java.net.InetAddress a;
            try {
                a = java.net.InetAddress.getByName(config.gcAddress());
            } catch (java.net.UnknownHostException e) {
                org.slf4j.LoggerFactory.getLogger(Console.class).warn("--gc-address {}: unknown host; believing no "
                        + "GameController until it resolves", config.gcAddress());
                return config.gcAddress();
            }
            return a.getHostAddress();
        }
        return config.gcMonitor() == null || config.gcMonitor().getAddress() == null ? null
                : config.gcMonitor().getAddress().getHostAddress();
    }

    /**
     * Which GameController the console believes (pinned: the first heard, or {@code --gc-address}),
     * the other sources sending game states, and what looked wrong (docs/security.md).
     */
    public GameControllerSources gcSources() {
        return gcSources;
    }

    /** The monitor of the field's GameController, or null when not asked for (or its port was taken). */
    public GcMonitor gcMonitor() {
        return gcMonitor;
    }

    /**
     * The robots as the field's GameController sees them at {@code nowMs} (wall time, ms), when
     * this console is its monitor; empty otherwise.
     */
    public Optional<touchline.app.game.MonitorReport> monitorReport(long nowMs) {
        GcMonitor m = gcMonitor;
        return m == null ? Optional.empty()
                : Optional.of(new touchline.app.game.MonitorReport(m.robots().size(), m.describe(nowMs)));
    }

    private void tick() {
        try {
            robots.tick();
            options.tick();
            matchMode.refresh(); // a claim of play expires with time: held requests go out then
            robotWaits.tick();
            bridges.tick();
        } catch (RuntimeException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("tick failed: {}", e.toString());
        }
    }

    public SendResult setOption(int robotId, String option, boolean on) {
        if (remote != null) {
            return SendResult.failed(COMMANDS_OFF);
        }
        SendResult result = options.setWanted(robotId, option, on);
        WantedOptionsFile f = wantedFile;
        if (f != null) {
            f.write(options.allWanted());
        }
        return result;
    }

    /**
     * Switches an option off that the user names, even one another console switched on (the
     * {@code options --off} command); {@link #setOption} only switches off what this console's
     * user switched on.
     */
    public SendResult switchOptionOff(int robotId, String option) {
        if (remote != null) {
            return SendResult.failed(COMMANDS_OFF);
        }
        SendResult result = options.switchOff(robotId, option);
        WantedOptionsFile f = wantedFile;
        if (f != null) {
            f.write(options.allWanted());
        }
        return result;
    }

    /**
     * A switch a tool asked for (the {@code options} command, here or through this console's live
     * server): on is wanted by this console from now on, off switches the option off whoever
     * switched it on; both pass match mode.
     */
    public SendResult switchOptionAsAsked(int robotId, String option, boolean on) {
        return on ? setOption(robotId, option, true) : switchOptionOff(robotId, option);
    }

    /**
     * Whether an option shows as on (its box in the options view, [x] in {@code options}): wanted
     * by this console; viewing a remote Touchline, on on the robot as the serving console hears it.
     */
    public boolean optionShownOn(touchline.model.OptionState option) {
        return remote != null ? option.enabledOnRobot() : option.wanted();
    }

    /**
     * Asks the remote Touchline this console views to switch an option ({@link #switchOptionAsAsked}
     * there, through its match mode); completes with its answer. Not viewing one: "not sent" at once.
     */
    public java.util.concurrent.CompletableFuture<SendResult> switchOptionRemotely(int robotId, String option, boolean on) {
        touchline.transport.remote.RemoteStream r = remote;
        return r == null ? java.util.concurrent.CompletableFuture.completedFuture(SendResult.failed("not viewing a remote Touchline"))
                : r.switchOption(robotId, option, on);
    }

    /**
     * Keeps the wanted debug options in {@code file} (beside the layouts): what it holds from an
     * earlier run is wanted again now, each robot getting its options when it appears, and every
     * switch from now on is written there. A file that cannot be read or written only costs the
     * remembering ({@link #wantedOptionsProblem()}). Viewing a remote Touchline, nothing: the
     * options are the serving console's, and this one wants none of its own.
     */
    public void rememberWantedOptions(Path file) {
        if (remote != null) {
            return;
        }
        WantedOptionsFile f = new WantedOptionsFile(file);
        options.restoreWanted(f.read());
        wantedFile = f;
    }

    /** Why the wanted options could not be read or kept, or empty. */
    public String wantedOptionsProblem() {
        WantedOptionsFile f = wantedFile;
        return f == null ? "" : f.problem();
    }

    /**
     * Watches another Touchline (its {@code touchline serve}, or its window serving to viewers)
     * instead of the field: its robots' envelopes enter this console's stream marked
     * {@link touchline.transport.Origin#REMOTE}, so every view works as on live robots, and from
     * now on every command is refused with {@link #COMMANDS_OFF} (debug options, the reliable
     * stream, the GameController) — the remote console is the one talking to the robots. The
     * connection reconnects by itself; its status is {@link #remote()}'s. The remote console's
     * GameController packets, NAO frames and malformed datagrams come too (as their bytes), and
     * its GameController's state drives this console's match mode.
     *
     * @param tls trust for a {@code wss://} server, or null
     */
    public synchronized touchline.transport.remote.RemoteStream viewRemote(java.net.URI url, javax.net.ssl.SSLContext tls) {
        if (remote != null) {
            remote.close();
        }
        setGate(() -> Optional.of(COMMANDS_OFF));
        stopGameController();
        // the remote field's GameController drives this console's match mode (shown; nothing is sent anyway)
        remote = new touchline.transport.remote.RemoteStream(url, tls, codec, new RemoteGameState(matchMode, live),
                java.time.Duration.ofSeconds(5));
        return remote.start();
    }

    /** The connection to the remote Touchline this console views, in words and figures, if it views one. */
    public Optional<touchline.transport.remote.RemoteStatus> remoteStatus() {
        return remote().map(touchline.transport.remote.RemoteStream::status);
    }

    /** The remote Touchline this console views, if it views one. */
    public Optional<touchline.transport.remote.RemoteStream> remote() {
        return Optional.ofNullable(remote);
    }

    public EnvelopeBus bus() { return bus; }
    /** The team's ROS 2 robots behind their Foxglove bridges (issue 39). */
    public touchline.app.bridges.RosBridges bridges() { return bridges; }
    public RobotRegistry robots() { return robots; }
    public DebugOptionSession options() { return options; }
    public TrafficMeter traffic() { return traffic; }

    /**
     * The UDP transport itself: for this package and the tests' fixture only. The faces use the
     * core's use cases ({@link #port()}, {@link #transportCounts()}, {@link #openStream}, ...),
     * never the transport (ArchitectureTest keeps it so).
     */
    UdpTransport udp() { return udp; }

    /** The UDP port robots send to (the one bound: a port of 0 asked for any free one). */
    public int port() {
        return udp.localPort();
    }

    /**
     * Stops or resumes reading from the robots' socket: while stopped, datagrams wait in the
     * socket's receive buffer (beyond it the kernel drops them). Returns once applied. The ingest
     * benchmark measures how fast a filled buffer is drained with this.
     */
    public void setReading(boolean on) throws InterruptedException {
        udp.setReading(on);
    }

    /**
     * The UDP transport in use and why (epoll + recvmmsg, or the portable NIO), and where its two
     * ingest threads run, in words.
     */
    public String transportDescription() {
        return udp.description();
    }

    /** The UDP transport's counts of datagrams and bytes in and out, now. */
    public TransportCounts transportCounts() {
        return TransportCounts.of(udp.counters(), teamDatagramsIn.get(), teamBytesIn.get());
    }

    /**
     * Opens (or returns) the reliable stream with a robot at {@code peer}: lossless, in-order
     * bytes both ways, gated by match mode like every command (held segments go out when play
     * stops; viewing a remote Touchline they never go).
     */
    public ReliableSession openStream(InetSocketAddress peer) {
        return reliable.open(peer);
    }

    /**
     * Waits until the live robot {@code robotId} has been heard from an address (at most
     * {@code timeout}, by the console's clock); empty if it was not.
     */
    public Optional<RobotSnapshot> waitForRobot(int robotId, java.time.Duration timeout) throws InterruptedException {
        return robotWaits.await(() -> robots.robot(robotId).filter(r -> r.address() != null), timeout.toNanos() / 1000);
    }

    /**
     * Adds the team's own message types (from a descriptor set, {@code record.SchemaSet}) to
     * the kinds this console decodes, renders, records and serves; returns one sentence per file
     * that could not be used (the others are used).
     */
    public List<String> loadTeamSchemas(List<com.google.protobuf.Descriptors.FileDescriptor> files) {
        return List.copyOf(kinds.add(files).values());
    }

    /**
     * Loads a team's own message types from a protoc descriptor set (the replay view's
     * <i>Team schemas</i>): from then on they are decoded, rendered, recorded and served by name.
     * Throws with a user-facing message when the file is not a usable descriptor set.
     */
    public TeamSchemas.Outcome loadTeamSchemas(Path descriptorSet) throws RecordingException {
        return teamSchemas.load(descriptorSet);
    }

    /** Match mode as the JSON the live server serves ({@code /touchline/matchMode}). */
    public MatchModeJson matchModeJson() {
        return new MatchModeJson(matchMode);
    }

    /**
     * The console's state the live server serves as JSON channels, each made by the face's
     * {@code maker} ({@code touchline.serve.JsonChannel::new}): match mode
     * ({@code /touchline/matchMode}) and the team-message budget ({@code /team/budget}). A new
     * state channel is added here, and every face serving the console serves it.
     */
    public <T> List<T> servedStateChannels(StateChannelMaker<T> maker) {
        MatchModeJson mode = matchModeJson();
        TeamBudgetJson budget = teamBudgetJson();
        return List.of(maker.channel(MatchModeJson.TOPIC, MatchModeJson.SCHEMA_NAME, MatchModeJson.SCHEMA, mode::now),
                maker.channel(TeamBudgetJson.TOPIC, TeamBudgetJson.SCHEMA_NAME, TeamBudgetJson.SCHEMA, budget::now));
    }

    /** The version, runtime and portable fallbacks in use (the window's Help → About and status bar). */
    public RuntimeReport runtime() {
        return RuntimeReport.ofThisProcess(udp.backend()).withUdpCores(udp.cores());
    }
    /** The reliable streams: for this package and the tests' fixture only (faces: {@link #openStream}). */
    ReliableStreamHandler reliable() { return reliable; }

    /** Match mode and the like: what may go to robots right now (GameController packets aside). */
    public void setGate(SendGate gate) {
        if (remote != null) {
            return; // viewing a remote Touchline: the gate stays shut
        }
        this.gate = gate;
        udp.setGate(gate);
        reliable.setGate(gate);
    }

    /**
     * Connects to a NAO ({@code rpcPort}, and its camera at {@code camPort} unless 0): every call
     * and move of the session passes this console's gate (match mode, a remote view) and its
     * traffic enters this console's stream. Several NAOs may be connected at once; closing a
     * session disconnects it.
     *
     * @param keys CURVE client keys, or null: insecure
     */
    public NaoSession connectNao(String host, int rpcPort, int camPort, touchline.transport.nao.NaoClientKeys keys,
                                 touchline.transport.nao.NaoLinkConfig naoConfig) {
        // held NAO commands are dropped, never sent when play stops: say so instead of the debug requests' promise
        SendGate naoGate = () -> gate.holdReason().map(r -> r.endsWith(SENT_LATER)
                ? r.substring(0, r.length() - SENT_LATER.length()) + "; not sent" : r);
        NaoSession session = new NaoSession(host, rpcPort, camPort, naoConfig, keys, live, naoGate, clock, realClock,
                naos::remove);
        naos.add(session);
        return session;
    }

    /**
     * Opens a NAO's camera server alone (no RPC link), its frames entering this console's stream
     * ({@link #naoCamera()}); fetching frames sends no command, so match mode does not hold it.
     * Closing it (or the console) stops it.
     *
     * @param keys CURVE client keys, or null: insecure
     */
    public NaoCamera connectNaoCamera(String host, int camPort, touchline.transport.nao.NaoClientKeys keys) {
        NaoCamera camera = new NaoCamera(host, camPort, live, keys, clock, realClock, naoCameras::remove);
        naoCameras.add(camera);
        return camera;
    }

    /**
     * The NAO cameras' newest frame and rates as this console's stream carries them: frames of
     * the NAOs connected here, of a remote Touchline's NAO when viewing one, and of a replay.
     */
    public NaoCameraFeed naoCamera() {
        return naoCamera;
    }

    /** The NAO calls' newest outcome in words as this console's stream carries them (here, a remote Touchline's, replayed). */
    public NaoCallFeed naoCalls() {
        return naoCalls;
    }

    /** Forgets what the faces show of a replay (the view stores and the NAO feeds) as of {@code startMicros}. */
    private void restartReplayedViews(long startMicros) {
        stores.restartReplay(startMicros);
        naoCamera.restartReplay();
        naoCalls.restartReplay();
    }

    /** The NAOs connected through this console, oldest first. */
    public List<NaoSession> naoSessions() {
        return List.copyOf(naos);
    }
    public MessageKinds kinds() { return kinds; }
    /** The message codec: for this package and the tests' fixture only. */
    MessageCodec codec() { return codec; }
    public MicrosClock clock() { return clock; }
    /** Monotonic milliseconds for a game a face sets up ({@link #startGameController}). */
    public GameClock gameClock() { return realClock; }

    /** The traffic meter's "now": wall time, or the replay position while a replay plays with live listening paused. */
    public MicrosClock modelClock() { return modelClock; }
    /** The replay's position (wall time while none is open): the "now" of replayed robots. */
    public MicrosClock replayClock() { return replayClock; }
    public MatchMode matchMode() { return matchMode; }
    /**
     * The bounded stores the UI's views pull from once per frame: the replay's while one is
     * open (opening it is asking to look at it), else the live ones. Live data keeps arriving
     * in the live stores meanwhile; both stay reachable by origin.
     */
    public touchline.model.store.ViewStores stores() { return stores; }

    /** Starts recording every envelope (in and out, live or replayed) into an MCAP file. */
    public synchronized Recorder startRecording(Path file) throws IOException {
        stopRecording();
        recorder = new Recorder(file, EnvelopeWriter.Options.defaults().withBridgedSchemas(bridges::schemaOf));
        recorderSubscription = bus.subscribe(recorder);
        return recorder;
    }

    /** Stops and closes the recording; the file is complete (footer and index) afterwards. */
    public synchronized void stopRecording() throws IOException {
        if (recorder != null) {
            closeQuietly(recorderSubscription);
            recorder.close();
            recorder = null;
        }
    }

    /**
     * Ends the recording, as {@link #stopRecording()}, waiting at most {@code timeoutMillis}
     * for the file to be finished: what a face calls on its way out (the window closing, a
     * signal), where the process must not hang on a stuck disk. True when the file is finished
     * (or nothing was recording).
     */
    public boolean finishRecording(long timeoutMillis) {
        Thread finishing = new Thread(() -> {
            try {
                stopRecording();
            } catch (IOException e) {
                org.slf4j.LoggerFactory.getLogger(Console.class).warn("finishing the recording: {}", e.toString());
            }
        }, "touchline-finish-recording");
        finishing.start();
        try {
            finishing.join(timeoutMillis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return !finishing.isAlive();
    }

    public synchronized Optional<RecorderStats> recording() {
        return recorder == null ? Optional.empty() : Optional.of(recorder.stats());
    }

    /**
     * Opens a recording and plays it into the same stream as live traffic (paused at its
     * start). Its envelopes are marked replayed: they never cause a datagram, never change
     * match mode, and fill the model beside the live robots, never merged with them. Each
     * jump of the replay (a seek, a loop going round) starts its robots and stores afresh.
     */
    public synchronized Replay openReplay(Path file) throws RecordingException {
        return openReplay(List.of(file), Map.of());
    }

    /**
     * Opens several recordings (the laptop's and robots' own logs) as one replay on one
     * timeline, as {@link #openReplay(Path)} does one: each file's clock is moved onto the first
     * file's by the offset given in {@code offsets} (µs, the file's clock minus the first's) or
     * else by the GameController packets both files heard (this reads each file once: call it
     * off the UI thread). A robot heard in two files is one replayed robot.
     */
    public synchronized Replay openReplay(List<Path> files, Map<Path, Long> offsets) throws RecordingException {
        closeReplay();
        ReplaySession session = ReplaySession.open(files, offsets, kinds);
        long start = session.startMicros();
        restartReplayedViews(start);
        replay = new Replay(session, bus, realClock, () -> {
            restartReplayedViews(start);
            robots.forgetReplayed();
        });
        return replay;
    }

    public synchronized Optional<Replay> replay() {
        return Optional.ofNullable(replay);
    }

    /** Closes the replay; its robots, options and stores go with it, live ones stay. */
    public synchronized void closeReplay() {
        if (replay != null) {
            replay.close();
            replay = null;
            robots.forgetReplayed();
            options.forgetReplayed();
            restartReplayedViews(clock.nowMicros());
        }
    }

    /**
     * Starts refereeing: the embedded GameController sends {@code game}'s state to {@code config}'s
     * destinations, publishes its packets into the Envelope stream and tells match mode what it
     * sends. One at a time; a running one is stopped first.
     */
    public synchronized EmbeddedGameController startGameController(Game game, GcConfig gcConfig) throws IOException {
        return startGameController((RefereedGame) game, gcConfig);
    }

    /**
     * Starts refereeing a game of any rules: an {@link touchline.game.hsl.HslGame} in the HSL
     * formats, an HL {@link Game} in the others (a mismatch is refused with the reason).
     */
    public synchronized EmbeddedGameController startGameController(RefereedGame game, GcConfig gcConfig)
            throws IOException {
        if (remote != null) {
            throw new IOException(COMMANDS_OFF);
        }
        stopGameController();
        EmbeddedGameController gc = new EmbeddedGameController(game, gcConfig, live, matchMode, clock);
        try {
            gc.start();
        } catch (RuntimeException e) {
            gc.close();
            throw new IOException(e.getMessage(), e);
        }
        gameController = gc;
        return gc;
    }

    public synchronized Optional<EmbeddedGameController> gameController() {
        return Optional.ofNullable(gameController);
    }

    public synchronized void stopGameController() {
        if (gameController != null) {
            gameController.close();
            gameController = null;
        }
    }

    /** Live listening on or paused (a replay may run beside live traffic or alone). */
    public void setLiveListening(boolean on) {
        live.setLive(on);
    }

    public boolean liveListening() {
        return live.isLive();
    }

    private static void closeQuietly(AutoCloseable c) {
        try {
            if (c != null) {
                c.close();
            }
        } catch (Exception ignored) {
            // unsubscribing cannot fail
        }
    }

    /**
     * Starts the budget guard for {@code team} under {@code profile}: listens to the team's
     * messages on {@code bind} (usually 0.0.0.0:10000+team) and counts them against the
     * profile's budget, with the GameController's own figure when one is heard. A second call
     * replaces the first.
     */
    public synchronized TeamMessageBudget guardTeamMessages(RuleProfile profile, int team, InetSocketAddress bind)
            throws IOException {
        stopGuardingTeamMessages();
        budget = new TeamMessageBudget(modelClock, profile, team);
        budgetSubscription = bus.subscribe(budget);
        debugRate = new DebugRateGuard(clock, profile);
        debugRateSubscription = bus.subscribe(debugRate);
        teamMessages = new TeamMessageListener(bind, e -> {
            teamDatagramsIn.incrementAndGet();
            teamBytesIn.addAndGet(e.size());
            live.accept(e);
        }, clock);
        return budget;
    }

    /** The port a team's messages go to by the rules (10000 + team). */
    public int defaultTeamMessagePort(int team) {
        return TeamMessageListener.portOf(team);
    }

    /** The port the team's messages are heard on, or -1 without a budget guard. */
    public synchronized int teamMessagePort() {
        try {
            return teamMessages == null ? -1 : teamMessages.localAddress().getPort();
        } catch (IOException e) {
            return -1;
        }
    }

    /** Robots over the profile's debug-packet limit during play, if the guard was started. */
    public synchronized Optional<DebugRateGuard> debugRateGuard() {
        return Optional.ofNullable(debugRate);
    }

    /** The budget guard's meter as JSON, for serving ({@code /team/budget}); its state is null without a guard. */
    public TeamBudgetJson teamBudgetJson() {
        return new TeamBudgetJson(this::teamMessageBudget);
    }

    /** The budget guard, if started. */
    public synchronized Optional<TeamMessageBudget> teamMessageBudget() {
        return Optional.ofNullable(budget);
    }

    public synchronized void stopGuardingTeamMessages() {
        if (teamMessages != null) {
            teamMessages.close();
            teamMessages = null;
        }
        for (AutoCloseable subscription : new AutoCloseable[]{budgetSubscription, debugRateSubscription}) {
            try {
                if (subscription != null) {
                    subscription.close();
                }
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }
        budgetSubscription = null;
        debugRateSubscription = null;
        budget = null;
        debugRate = null;
    }

    @Override
    public void close() {
        bridges.close();
        for (NaoSession nao : naos) {
            nao.close();
        }
        for (NaoCamera camera : naoCameras) {
            camera.close();
        }
        if (remote != null) {
            remote.close();
        }
        stopGuardingTeamMessages();
        stopGameController();
        closeReplay();
        try {
            stopRecording();
        } catch (IOException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("closing the recording: {}", e.toString());
        }
        ticker.shutdownNow();
        if (gcWatch != null) {
            gcWatch.close();
        }
        if (gcMonitor != null) {
            gcMonitor.close();
        }
        udp.close();
    }
}
