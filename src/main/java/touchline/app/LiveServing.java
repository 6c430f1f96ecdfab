package touchline.app;

import touchline.app.game.MatchMode;
import touchline.app.game.MatchModeJson;
import touchline.serve.FoxgloveServer;
import touchline.serve.JsonChannel;
import touchline.serve.ServeConfig;
import touchline.serve.Serving;

import java.util.List;
import java.util.Optional;

/**
 * Serving this console's stream to viewers (Foxglove, Lichtblick, another Touchline): one live
 * server at a time, with the console's state as JSON channels (match mode, the team budget) and,
 * when asked, the viewers' option switches passed to {@link OptionSwitches}. What
 * {@code touchline serve} and the window's "Serve to viewers" both start.
 */
public final class LiveServing {

    private final LiveField field;
    private final MatchMode matchMode;
    private final TeamBudget budget;
    private final OptionSwitches switches;
    private Serving serving;

    LiveServing(LiveField field, MatchMode matchMode, TeamBudget budget, OptionSwitches switches) {
        this.field = field;
        this.matchMode = matchMode;
        this.budget = budget;
        this.switches = switches;
    }

    /**
     * Binds and starts serving (a running server is stopped first); IllegalArgumentException (a
     * sentence for the user) for a configuration that cannot be served, the bind's own exception
     * when the port cannot be had. Serves the live stream: viewers may switch debug options
     * ({@code touchline options --connect}), through match mode.
     */
    public FoxgloveServer start(ServeConfig config) throws InterruptedException {
        return start(config, false);
    }

    /**
     * As {@link #start(ServeConfig)}, but serves the replay stream ({@code serve --replay}): what an
     * open replay plays, and no option switches (a replay never acts on the field).
     */
    public FoxgloveServer startReplay(ServeConfig config) throws InterruptedException {
        return start(config, true);
    }

    private synchronized FoxgloveServer start(ServeConfig config, boolean replay) throws InterruptedException {
        stop();
        Serving s = new Serving(config, field.kinds(), field.clock(), replay ? field.replayStream() : field.bus(),
                stateChannels());
        boolean started = false;
        try {
            s.start();
            started = true;
        } finally {
            if (!started) { // a port in use: nothing is left half-started
                s.close();
            }
        }
        if (!replay) {
            s.server().offerOptionSwitches(switches::switchAsAsked);
        }
        serving = s;
        return s.server();
    }

    /**
     * The console's state the live server serves as JSON channels: match mode
     * ({@code /touchline/matchMode}) and the team-message budget ({@code /team/budget}). A new
     * state channel is added here, and every face serving the console serves it.
     */
    public List<JsonChannel> stateChannels() {
        MatchModeJson mode = new MatchModeJson(matchMode);
        TeamBudgetJson meter = budget.json();
        return List.of(new JsonChannel(MatchModeJson.TOPIC, MatchModeJson.SCHEMA_NAME, MatchModeJson.SCHEMA, mode::now),
                new JsonChannel(TeamBudgetJson.TOPIC, TeamBudgetJson.SCHEMA_NAME, TeamBudgetJson.SCHEMA, meter::now));
    }

    /** Stops serving; the viewers are disconnected. */
    public synchronized void stop() {
        if (serving != null) {
            serving.close();
            serving = null;
        }
    }

    /** The live server while serving. */
    public synchronized Optional<FoxgloveServer> server() {
        return Optional.ofNullable(serving).map(Serving::server);
    }

    void close() {
        stop();
    }
}
