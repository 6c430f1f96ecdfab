package touchline.app;

import touchline.app.game.MatchMode;
import touchline.transport.MicrosClock;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * The composition root of the application core both faces share: it builds the use-case
 * services from a {@link ConsoleConfig}, starts them and closes them in reverse order. A face
 * takes the one or two services it needs ({@link #field()}, {@link #referee()}, ...), never the
 * Console (ArchitectureTest names the few places that compose). A new service is a small class
 * in this package (or {@code app.<feature>}), built in the constructor with a line, handed out
 * by one accessor, and closed in {@link #close()}.
 */
public final class Console implements AutoCloseable {

    /** Why a console viewing another Touchline's stream sends nothing: every command path says this. */
    public static final String COMMANDS_OFF = RemoteView.COMMANDS_OFF;

    private final ConsoleConfig config;
    private final TeamSchemas teamSchemas;
    private final LiveField field;
    private final Referee referee;
    private final RemoteView remote;
    private final OptionSwitches switches;
    private final Naos naos;
    private final Recordings recordings;
    private final Replays replays;
    private final TeamBudget budget;
    private final LiveServing serving;
    private final ScheduledExecutorService ticker;

    public Console(ConsoleConfig config) {
        this(config, new SystemClock());
    }

    public Console(ConsoleConfig config, MicrosClock clock) {
        this(config, clock, true);
    }

    /** @param withModel false leaves the model unsubscribed (benchmarks of the bare transport) */
    public Console(ConsoleConfig config, MicrosClock clock, boolean withModel) {
        this.config = config;
        // The real clock's monotonic faces (match mode, the game, replay pacing); stateless, like every SystemClock.
        SystemClock realClock = new SystemClock();
        ReplaySlot replay = new ReplaySlot();
        MatchMode matchMode = new MatchMode(realClock);
        field = new LiveField(config, clock, withModel, replay);
        teamSchemas = new TeamSchemas(field.kinds());
        field.bus().subscribe(field.unpacking(new ReportedGameState(matchMode))); // a digest's Status too
        FieldGate gate = new FieldGate(field, matchMode);
        referee = new Referee(config, field.live(), matchMode, clock, realClock, gate::commandsOff);
        recordings = new Recordings(field.bus());
        naos = new Naos(field, gate, clock, realClock, replay);
        replays = new Replays(field, naos, realClock, replay);
        budget = new TeamBudget(field);
        remote = new RemoteView(field, referee, gate);
        switches = new OptionSwitches(field.options(), remote);
        serving = new LiveServing(field, matchMode, budget, switches);
        ticker = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "touchline-tick");
            t.setDaemon(true);
            return t;
        });
    }

    /** Binds the UDP port, listens for GameControllers and starts the model's clock; returns this for chaining. */
    public Console start() throws InterruptedException {
        field.start();
        referee.listen();
        ticker.scheduleAtFixedRate(this::tick, config.tickMillis(), config.tickMillis(), TimeUnit.MILLISECONDS);
        return this;
    }

    private void tick() {
        try {
            field.tick();
            referee.tick();
            field.tickWaits();
            switches.keepMatch();
        } catch (RuntimeException e) {
            org.slf4j.LoggerFactory.getLogger(Console.class).warn("tick failed: {}", e.toString());
        }
    }

    /** The field as heard: the robots' port, the stream and its read models. */
    public LiveField field() { return field; }
    /** Match mode, the GameControllers heard, the embedded GameController. */
    public Referee referee() { return referee; }
    /** Watching another Touchline instead of the field. */
    public RemoteView remote() { return remote; }
    /** Switching debug options, and the wanted ones remembered. */
    public OptionSwitches optionSwitches() { return switches; }
    /** The NAOs driven through the console and what their feeds carry. */
    public Naos naos() { return naos; }
    /** Recording the stream to MCAP. */
    public Recordings recordings() { return recordings; }
    /** Replaying recordings into the stream. */
    public Replays replays() { return replays; }
    /** The team-message budget guard. */
    public TeamBudget teamBudget() { return budget; }
    /** The team's own message types (the one way to load them). */
    public TeamSchemas teamSchemas() { return teamSchemas; }
    /** Serving the stream to viewers. */
    public LiveServing serving() { return serving; }

    /** Closes the services in the reverse order of their making. */
    @Override
    public void close() {
        serving.close();
        remote.close();
        budget.stop();
        replays.close();
        naos.close();
        recordings.close();
        ticker.shutdownNow();
        referee.close();
        field.close();
    }
}
