package touchline.ui.referee;

import touchline.app.Referee;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.SenderPriority;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.game.RefereedGame;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.transport.HostPort;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;
import touchline.transport.gamecontroller.MonitorStats;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.IntSupplier;

/**
 * What the GameController tab decides, without JavaFX: the game and configuration a setup starts
 * (or why it cannot), the setup remembered for the next start, which running GameController the
 * tab shows (started here or elsewhere), its header, sender priority and monitors lines, match
 * mode's notice, and whether an override may be set. The tab binds these to its controls.
 */
final class GameControllerTabModel {

    private final Referee referee;
    private final IntSupplier requestsWaiting;
    private final RememberedSetup remembered;
    private EmbeddedGameController shown;
    private java.util.concurrent.CompletableFuture<Void> stopping; // null: no stop asked for here
    private java.util.concurrent.CompletableFuture<EmbeddedGameController> starting; // null: no start asked for here
    /** The monitors line of the start in progress, written on its thread before it completes. */
    private volatile String startingMonitorLine = "";
    /** Where monitors register, or why not; empty for a GameController started elsewhere. */
    private String monitorLine = "";

    /**
     * @param referee         the console's referee: match mode and the embedded GameController
     * @param requestsWaiting how many requests to robots wait right now (the status bar's count)
     * @param settingsDir     where the last setup is remembered; null remembers nothing
     */
    GameControllerTabModel(Referee referee, IntSupplier requestsWaiting, Path settingsDir) {
        this.referee = referee;
        this.requestsWaiting = requestsWaiting;
        this.remembered = new RememberedSetup(settingsDir);
    }

    /** The form as it opens: the defaults with what was remembered. */
    GameSetup initialSetup() {
        return remembered.restore(GameSetup.defaults());
    }

    /**
     * Asks to start refereeing the game {@code setup} describes (a running one is stopped first)
     * and remembers the setup; returns at once with the line for under the form: "starting…",
     * or why it cannot start. {@link #started()} says, at a later frame, when it runs (then
     * {@link #shown()} is it) or why it did not.
     */
    String start(GameSetup setup) {
        if (stopping != null && !stopping.isDone()) {
            return "cannot start yet: the GameController is still stopping";
        }
        if (starting != null) {
            return "cannot start yet: the GameController is still starting";
        }
        try {
            GcProfile profile = setup.profile();
            if (profile == null) {
                return "choose a format";
            }
            List<InetSocketAddress> dests = new ArrayList<>();
            for (String d : setup.destinations().split(",")) {
                if (!d.isBlank()) {
                    dests.add(HostPort.parse(d, GcProfile.GAME_STATE_PORT).resolved());
                }
            }
            if (dests.isEmpty()) {
                return "give at least one destination";
            }
            int a = Integer.parseInt(setup.teamA().strip());
            int b = Integer.parseInt(setup.teamB().strip());
            GcConfig defaults = GcConfig.defaults(profile);
            int returns = setup.returnPort().isBlank() ? profile.defaultReturnPort()
                    : Integer.parseInt(setup.returnPort().strip());
            GcConfig config = new GcConfig(profile, false, dests, null, new InetSocketAddress("0.0.0.0", returns),
                    defaults.rivalBind(), GcConfig.INTERVAL_MS, setup.realtime());
            RefereedGame game;
            if (profile.hsl()) {
                String wrong = a == b ? "the two teams need different numbers"
                        : HslGame.colourConflict(setup.coloursA(), setup.coloursB());
                if (wrong != null) {
                    return "cannot start: " + wrong;
                }
                game = new HslGame(HslRules.forVersion(profile.hslVersion(), setup.competition()), a, setup.coloursA(),
                        b, setup.coloursB(), referee.gameClock());
            } else {
                game = new Game(LeagueParams.hlSimulationKidSize(), a, 1, b, 0, referee.gameClock());
            }
            Integer monitorPort = profile.hsl() ? monitorPort(setup) : null;
            remembered.save(setup);
            startingMonitorLine = "";
            starting = referee.startInBackground(game, config, gc -> {
                if (monitorPort != null) {
                    startingMonitorLine = serveMonitors(gc, monitorPort);
                }
            });
            return "starting…";
        } catch (NumberFormatException e) {
            return "team numbers and ports are whole numbers: " + e.getMessage();
        } catch (RuntimeException e) {
            return "cannot start: " + e.getMessage();
        }
    }

    /**
     * At a frame: once a start asked for here is done (once), the line for under the form: empty
     * when it runs (then {@link #shown()} is it), else why it did not start.
     */
    Optional<String> started() {
        if (starting == null || !starting.isDone()) {
            return Optional.empty();
        }
        java.util.concurrent.CompletableFuture<EmbeddedGameController> done = starting;
        starting = null;
        try {
            shown = done.join();
            monitorLine = startingMonitorLine;
            return Optional.of("");
        } catch (java.util.concurrent.CompletionException e) {
            Throwable why = e.getCause() == null ? e : e.getCause();
            return Optional.of("cannot start: " + why.getMessage());
        }
    }

    /**
     * Where monitor applications (the official TeamCommunicationMonitor, a console with
     * --gc-monitor) register, as with the official GameController; null for none (left empty).
     */
    private static Integer monitorPort(GameSetup setup) {
        String t = setup.monitorPort().strip();
        return t.isEmpty() ? null : Integer.parseInt(t);
    }

    /** Answers monitors as the official GameController does; a busy port costs only that (said in the tab). */
    private static String serveMonitors(EmbeddedGameController gc, int port) {
        try {
            gc.serveMonitors(new InetSocketAddress("0.0.0.0", port), GcProfile.GAME_STATE_PORT, ForwardedReturnPacket.PORT);
            return "monitors register on UDP " + gc.monitorRequestAddress().getPort();
        } catch (IOException e) {
            return "no monitors: cannot listen on UDP " + port + " (" + e.getMessage() + ")";
        }
    }

    /**
     * Asks the running GameController to stop and returns at once; the tab shows the form again
     * with the returned line, and {@link #stopped()} says when the stop is done.
     */
    String stop() {
        stopping = referee.stopInBackground();
        shown = null;
        return "stopping…";
    }

    /** At a frame: the line once a stop asked for here is done (once), else empty. */
    Optional<String> stopped() {
        if (stopping == null || !stopping.isDone()) {
            return Optional.empty();
        }
        String line = stopping.isCompletedExceptionally() ? "stopped, with an error (see the log)" : "stopped";
        stopping = null;
        return Optional.of(line);
    }

    /** The GameController the tab shows; null while it shows the form. */
    EmbeddedGameController shown() {
        return shown;
    }

    /**
     * At a frame: whether the running GameController is no longer the one shown (started or
     * stopped elsewhere); then it becomes the one shown, without a monitors line (whoever
     * started it serves monitors or not). Not while a start asked for here is in progress.
     */
    boolean follow() {
        if (starting != null) {
            return false; // the start asked for here is shown with its monitors line by started()
        }
        EmbeddedGameController running = referee.gameController().orElse(null);
        if (running == shown) {
            return false;
        }
        shown = running;
        monitorLine = "";
        return true;
    }

    /** The running tab's header: the format and where it sends. */
    String header() {
        return shown == null ? "" : shown.config().profile().cliName() + " to " + shown.config().destinations();
    }

    /** The sender's priority in words. */
    String priority() {
        return shown == null ? "" : priorityText(shown.senderPriority());
    }

    static String priorityText(SenderPriority p) {
        return switch (p.kind()) {
            case REAL_TIME -> "Sender: real-time priority (500 ms cadence held under load)";
            case NOT_REQUESTED -> "Sender: normal priority";
            case STARTING -> "Sender: starting";
            case REFUSED -> "Sender: normal priority, real-time refused (" + p.why() + ")";
        };
    }

    /** Where monitors register (or why not), with how many are registered and refused once served. */
    String monitors() {
        MonitorStats served = shown == null ? null : shown.monitorStats();
        return served == null || monitorLine.isEmpty() ? monitorLine : monitorLine + "; "
                + served.monitors() + " of " + served.capacity() + " registered, "
                + (served.refusedFull() + served.badRequests()) + " refused";
    }

    /** Match mode's notice as the tab shows it; a warning while match mode holds the console's requests. */
    record Notice(String text, boolean warning) {
    }

    /**
     * Match mode's notice with the requests waiting now (the same words as the status bar:
     * attempts held back, retries counted, beside the requests waiting now).
     */
    Notice matchNotice() {
        String notice = referee.matchMode().notice();
        if (notice.isEmpty()) {
            return new Notice("Match mode: no game on; the console may talk to the robots.", false);
        }
        int waiting = requestsWaiting.getAsInt();
        return new Notice(notice + "; " + (waiting == 1 ? "1 request waiting now" : waiting + " requests waiting now"),
                true);
    }

    /**
     * Switches match mode's override (logged with its reason); returns why not when it is asked
     * for without a reason.
     */
    Optional<String> override(boolean on, String reason) {
        if (on && reason.isBlank()) {
            return Optional.of("An override needs a reason; it is logged.");
        }
        referee.matchMode().setOverride(on, reason.strip());
        return Optional.empty();
    }
}
