package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.game.ActionSyntax;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.app.game.MatchMode;
import touchline.game.Outcome;
import touchline.game.Penalty;
import touchline.game.RefereedGame;
import touchline.game.hsl.Competition;
import touchline.game.hsl.HslActionSyntax;
import touchline.game.hsl.HslGame;
import touchline.game.hsl.HslRules;
import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.protocol.gamecontroller.GameControlData;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.protocol.gamecontroller.HslPenalty;
import touchline.protocol.gamecontroller.TeamColour;
import touchline.protocol.gamecontroller.TeamInfo;
import touchline.app.SystemClock;
import touchline.app.Referee;
import touchline.app.game.EmbeddedGameController;
import touchline.app.game.GameRuntime;
import touchline.app.game.RefereeSnapshot;
import touchline.transport.HostPort;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;
import touchline.transport.gamecontroller.RobotLiveness;

import java.io.BufferedReader;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/**
 * {@code touchline gc}: the embedded GameController without a window. Sends the game state
 * every 500 ms in the chosen format, receives return packets, and takes referee actions from
 * stdin, one per line, printing every state change, robot request and warning.
 */
@Command(name = "gc", mixinStandardHelpOptions = true,
        description = {"Run the GameController headless; referee actions are read from stdin, one per line.",
                "", "Actions of the HSL formats (hsl20, hsl19; the 2026 rules):", HslActionSyntax.HELP,
                "", "Actions of the older formats (hl12, hl12-640, spl18, v8, v7):", ActionSyntax.HELP},
        footer = {"", "Example: printf 'kickoff 5\\nset\\nplay\\ngoal 5\\nstatus\\n' | ./touchline gc --team-a 5 "
                + "--team-b 14 --dest 127.0.0.1"})
public final class GcCommand implements Callable<Integer> {

    @Option(names = "--format", defaultValue = "hsl20",
            description = "wire format: hsl20 (HSL v20, 158 B, GameController 7.x, RoboCup 2026), hsl19 (HSL v19, "
                    + "198 B, GameController 6.0.x), hl12 (HL v12, 688 B), hl12-640 (HL v12 2017-2021, 640 B), spl18 "
                    + "(SPL v18, 118 B), v8 (2014, 158 B), v7 (2013, 116 B). The HSL formats referee under the "
                    + "2026 rules of that release. Default: ${DEFAULT-VALUE}")
    String format;

    @Option(names = "--competition", defaultValue = "middle_advanced",
            description = "HSL competition: small_foundation (4 players), small_advanced (7), middle_foundation (3), "
                    + "middle_advanced (5), large_foundation (3), large_advanced (5). Default: ${DEFAULT-VALUE}")
    String competition;

    @Option(names = "--team-a", required = true, description = "team number on the left, kicks off first")
    int teamA;

    @Option(names = "--team-b", required = true, description = "team number on the right")
    int teamB;

    @Option(names = "--colour-a", defaultValue = "red", description = "field player colour of team A: a name "
            + "(blue red yellow black white green orange purple brown gray) or its number. Default: ${DEFAULT-VALUE}")
    String colourA;

    @Option(names = "--colour-b", defaultValue = "blue", description = "field player colour of team B. "
            + "Default: ${DEFAULT-VALUE}")
    String colourB;

    @Option(names = "--goalkeeper-colour-a", defaultValue = "purple",
            description = "HSL: goalkeeper colour of team A. Default: ${DEFAULT-VALUE}")
    String goalkeeperColourA;

    @Option(names = "--goalkeeper-colour-b", defaultValue = "yellow",
            description = "HSL: goalkeeper colour of team B. Default: ${DEFAULT-VALUE}")
    String goalkeeperColourB;

    @Option(names = "--dest", paramLabel = "ADDRESS[:PORT]",
            description = "destination of game-state packets, repeatable (default 255.255.255.255:3838)")
    List<String> destinations = new ArrayList<>();

    @Option(names = "--return-port", description = "UDP port for return packets (default 3939; 3838 for v8/v7)")
    Integer returnPort;

    @Option(names = "--rival-port", description = "port to listen on for other GameControllers "
            + "(default 3838; -1 = do not listen)")
    Integer rivalPort;

    @Option(names = "--bind", defaultValue = "0.0.0.0", description = "local address of the receiving sockets")
    String bind;

    @Option(names = "--monitor-port", description = "HSL: UDP port where monitor applications (TeamCommunication"
            + "Monitor, a console with --gc-monitor) register for the true state and forwarded return packets "
            + "(default 3636; -1 = none)")
    Integer monitorPort;

    @Option(names = "--v7-compat", description = "also send the v7 compatibility packet every cycle")
    boolean v7Compat;

    @Option(names = "--players", description = "players per team of the older formats (default 4); "
            + "in HSL the competition decides")
    Integer players;

    @Option(names = "--half", description = "half length in seconds of the older formats (default 600); "
            + "in HSL the release's rules decide")
    Integer halfSeconds;

    @Option(names = "--realtime", negatable = true, defaultValue = "true", fallbackValue = "true",
            description = "real-time scheduling of the sender thread (Linux, root or CAP_SYS_NICE; on by default, "
                    + "the outcome is printed): keeps the 500 ms cadence on a busy laptop")
    boolean realtime;

    @Option(names = "--interval-ms", defaultValue = "500", hidden = true)
    long intervalMs;

    private final InputStream input;
    private final PrintStream out;

    public GcCommand() {
        this(System.in, System.out);
    }

    GcCommand(InputStream input, PrintStream out) {
        this.input = input;
        this.out = out;
    }

    /** The real clock, made once for this command (it has no console). */
    private final SystemClock clock = new SystemClock();

    @Override
    public Integer call() throws Exception {
        GcProfile profile = GcProfile.parse(format);
        if (profile == null) {
            out.println("error: unknown format '" + format + "' (" + GcProfile.names() + ")");
            return 2;
        }
        for (String d : destinations) {
            try {
                HostPort.parse(d, GcProfile.GAME_STATE_PORT);
            } catch (IllegalArgumentException e) {
                out.println("error: --dest " + e.getMessage());
                return 2;
            }
        }
        TeamColour[] a = {colour(colourA), colour(goalkeeperColourA)};
        TeamColour[] b = {colour(colourB), colour(goalkeeperColourB)};
        if (a[0] == null || a[1] == null || b[0] == null || b[1] == null) {
            out.println("error: unknown colour (blue red yellow black white green orange purple brown gray, or 0-9)");
            return 2;
        }
        RefereedGame referee;
        LineHandler handler;
        if (profile.hsl()) {
            Competition c = Competition.parse(competition);
            String wrong = c == null ? "unknown competition '" + competition + "'"
                    : players != null || halfSeconds != null
                    ? "--players and --half are for the older formats; in HSL the competition and release decide" : null;
            wrong = wrong != null ? wrong : teamA == teamB ? "the two teams need different numbers"
                    : HslGame.colourConflict(a, b);
            if (wrong != null) {
                out.println("error: " + wrong);
                return 2;
            }
            HslGame game = new HslGame(HslRules.forVersion(profile.hslVersion(), c), teamA, a, teamB, b,
                    clock);
            HslActionSyntax syntax = new HslActionSyntax();
            referee = game;
            handler = (line, owner) -> {
                HslActionSyntax.Parsed parsed = syntax.parse(line);
                return parsed.error() != null ? "error: " + parsed.error()
                        : outcome(GameRuntime.outcome(owner.perform(parsed.action())));
            };
        } else {
            LeagueParams params = LeagueParams.hlSimulationKidSize().withTeamSizeAndHalf(
                    players == null ? 4 : players, halfSeconds == null ? 600 : halfSeconds);
            Game game = new Game(params, teamA, a[0].ordinal(), teamB, b[0].ordinal(), clock);
            ActionSyntax syntax = new ActionSyntax();
            referee = game;
            handler = (line, owner) -> {
                ActionSyntax.Parsed parsed = syntax.parse(line, owner.snapshot().hl());
                return parsed.error() != null ? "error: " + parsed.error()
                        : outcome(GameRuntime.outcome(owner.perform(parsed.action())));
            };
        }
        return referee(profile, referee, handler);
    }

    /** What a line of stdin does to the game (through its owner); returns the line to print. */
    private interface LineHandler {
        String handle(String line, GameRuntime owner);
    }

    private static String outcome(Outcome o) {
        return (o.applied() ? "ok: " : "refused: ") + o.message();
    }

    private int referee(GcProfile profile, RefereedGame game, LineHandler handler) throws Exception {
        GcConfig config = config(profile);
        Referee referee = new Referee(e -> { }, new MatchMode(clock), clock);
        int monitorRequests = monitorPort != null ? monitorPort : MonitorRequest.PORT;
        try {
            EmbeddedGameController gc = referee.start(game, config, started -> {
                started.addEventListener(event -> print("! " + event));
                String[] last = {""};
                started.runtime().addListener(s -> {
                    String now = stateLine(s.description());
                    if (!now.equals(last[0])) {
                        last[0] = now;
                        print("state: " + now);
                    }
                });
                if (profile.hsl() && monitorRequests >= 0) {
                    started.serveMonitors(new InetSocketAddress(bind, monitorRequests),
                            GcProfile.GAME_STATE_PORT, ForwardedReturnPacket.PORT);
                    print("monitors register on " + started.monitorRequestAddress());
                }
            });
            print("GameController " + profile.cliName() + " sending to " + config.destinations() + ", returns on "
                    + gc.returnAddress() + (gc.rivalAddress() == null ? "" : ", watching " + gc.rivalAddress()));
            if (realtime) {
                String why = gc.awaitRealtimeOutcome(5000);
                print(why.isEmpty() ? "sender runs with real-time priority"
                        : "! no real-time priority (500 ms cadence may jitter on a busy machine): " + why);
            }
            GameRuntime owner = gc.runtime();
            print("state: " + owner.snapshot().description());
            BufferedReader in = new BufferedReader(new InputStreamReader(input, StandardCharsets.UTF_8));
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                String cmd = line.trim();
                if (cmd.isEmpty() || cmd.startsWith("#")) {
                    continue;
                }
                if (cmd.equals("quit") || cmd.equals("exit")) {
                    break;
                }
                if (cmd.equals("undo")) {
                    print(GameRuntime.outcome(owner.undo()).message());
                } else if (cmd.equals("status")) {
                    status(gc);
                } else {
                    print(handler.handle(cmd, owner));
                }
            }
            // The HSL schedule does not send a change at once: send the final state before closing.
            gc.sendNow();
            Thread.sleep(100);
        } finally {
            referee.stop();
        }
        return 0;
    }

    /** A colour by name or number, null when neither. */
    static TeamColour colour(String text) {
        String t = text.trim();
        if (!t.isEmpty() && t.chars().allMatch(Character::isDigit)) {
            return TeamColour.ofWire(Integer.parseInt(t));
        }
        for (TeamColour c : TeamColour.values()) {
            if (c.name().equalsIgnoreCase(t) || (c == TeamColour.GRAY && t.equalsIgnoreCase("grey"))) {
                return c;
            }
        }
        return null;
    }

    private static String stateLine(String d) {
        // Without timers: a change of the game, not of the clock.
        return d.replaceAll(", -?\\d+ s left, secondary -?\\d+ s", "");
    }

    private void status(EmbeddedGameController gc) {
        RefereeSnapshot game = gc.runtime().snapshot();
        print("status: " + game.description());
        print("packets sent: " + gc.packetsSent() + ", send errors: " + gc.sendErrors());
        long now = gc.runtime().now();
        GameControlData data = game.truth();
        for (var e : gc.liveness().all(now).entrySet()) {
            RobotLiveness.RobotKey k = e.getKey();
            TeamInfo team = data.team(k.team());
            print("robot " + k + ": " + e.getValue() + ", penalty "
                    + (team == null ? "-" : penaltyName(team.player(k.player()).penalty(), gc.config().profile().hsl())));
        }
        gc.badPackets().bySource().forEach((src, t) ->
                print("bad GameController packets from " + src + ": " + t.count() + " (last: " + t.lastReason() + ")"));
        if (gc.monitorStats() != null) {
            print("monitors: " + gc.monitorStats().describe());
        }
        String warning = gc.rivalWarning();
        if (!warning.isEmpty()) {
            print("! " + warning);
        }
    }

    private static String penaltyName(int neutral, boolean hsl) {
        if (hsl) {
            return HslPenalty.ofNeutral(neutral).name();
        }
        for (Penalty p : Penalty.values()) {
            if (p.code() == neutral) {
                return p.name();
            }
        }
        return String.valueOf(neutral);
    }

    private GcConfig config(GcProfile profile) {
        List<InetSocketAddress> dests = new ArrayList<>();
        for (String d : destinations) {
            dests.add(HostPort.parse(d, GcProfile.GAME_STATE_PORT).resolved());
        }
        GcConfig defaults = GcConfig.defaults(profile);
        if (dests.isEmpty()) {
            dests.addAll(defaults.destinations());
        }
        int returns = returnPort != null ? returnPort : profile.defaultReturnPort();
        InetSocketAddress rivals = null;
        int rival = rivalPort != null ? rivalPort : GcProfile.GAME_STATE_PORT;
        // In the 2014 profiles the return socket is the game-state port and hears rivals itself.
        if (rival >= 0 && rival != returns && !profile.returnsOnGameStatePort()) {
            rivals = new InetSocketAddress(bind, rival);
        }
        return new GcConfig(profile, v7Compat, dests, null, new InetSocketAddress(bind, returns), rivals,
                intervalMs, realtime);
    }

    private synchronized void print(String line) {
        out.println(line);
        out.flush();
    }

    /** Stand-alone entry point until {@code touchline.cli.Main} lists this command. */
}
