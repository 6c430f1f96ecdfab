package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.game.ActionSyntax;
import touchline.game.Game;
import touchline.game.GameClock;
import touchline.game.LeagueParams;
import touchline.game.MatchMode;
import touchline.game.Outcome;
import touchline.transport.gamecontroller.EmbeddedGameController;
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
                "", "Actions:", ActionSyntax.HELP},
        footer = {"", "Example: printf 'ready\\nset\\nplay\\ngoal 13\\nstatus\\n' | ./touchline gc --team-a 13 "
                + "--team-b 7 --dest 127.0.0.1"})
public final class GcCommand implements Callable<Integer> {

    @Option(names = "--format", defaultValue = "hl12",
            description = "wire format: hl12 (HL v12, 688 B), hl12-640 (HL v12 2017-2021, 640 B), spl18 "
                    + "(SPL v18, 118 B), v8 (2014, 158 B), v7 (2013, 116 B). Default: ${DEFAULT-VALUE}")
    String format;

    @Option(names = "--team-a", required = true, description = "team number on the left, kicks off first")
    int teamA;

    @Option(names = "--team-b", required = true, description = "team number on the right")
    int teamB;

    @Option(names = "--colour-a", defaultValue = "1", description = "colour of team A (0 blue, 1 red, ...). "
            + "Default: ${DEFAULT-VALUE}")
    int colourA;

    @Option(names = "--colour-b", defaultValue = "0", description = "colour of team B. Default: ${DEFAULT-VALUE}")
    int colourB;

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

    @Option(names = "--v7-compat", description = "also send the v7 compatibility packet every cycle")
    boolean v7Compat;

    @Option(names = "--players", defaultValue = "4", description = "players per team. Default: ${DEFAULT-VALUE}")
    int players;

    @Option(names = "--half", defaultValue = "600", description = "half length in seconds. Default: ${DEFAULT-VALUE}")
    int halfSeconds;

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

    @Override
    public Integer call() throws Exception {
        GcProfile profile = GcProfile.parse(format);
        if (profile == null) {
            out.println("error: unknown format '" + format + "' (hl12, hl12-640, spl18, v8, v7)");
            return 2;
        }
        GcConfig config = config(profile);
        LeagueParams params = LeagueParams.hlSimulationKidSize().withTeamSizeAndHalf(players, halfSeconds);
        Game game = new Game(params, teamA, colourA, teamB, colourB, GameClock.system());
        MatchMode matchMode = new MatchMode(GameClock.system());
        try (EmbeddedGameController gc = new EmbeddedGameController(game, config, e -> { }, matchMode)) {
            gc.addEventListener(event -> print("! " + event));
            String[] last = {""};
            game.addListener(() -> {
                String now = stateLine(game);
                if (!now.equals(last[0])) {
                    last[0] = now;
                    print("state: " + now);
                }
            });
            gc.start();
            print("GameController " + profile.cliName() + " sending to " + config.destinations() + ", returns on "
                    + gc.returnAddress() + (gc.rivalAddress() == null ? "" : ", watching " + gc.rivalAddress()));
            if (realtime) {
                String why = gc.sender().awaitRealtimeOutcome(5000);
                print(why.isEmpty() ? "sender runs with real-time priority"
                        : "! no real-time priority (500 ms cadence may jitter on a busy machine): " + why);
            }
            print("state: " + game.describe());
            ActionSyntax syntax = new ActionSyntax();
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
                    print(game.undo().message());
                } else if (cmd.equals("status")) {
                    status(gc);
                } else {
                    ActionSyntax.Parsed parsed = syntax.parse(cmd, game.snapshot());
                    if (parsed.error() != null) {
                        print("error: " + parsed.error());
                        continue;
                    }
                    Outcome o = game.perform(parsed.action());
                    print((o.applied() ? "ok: " : "refused: ") + o.message());
                }
            }
            // Let the last change go out before closing (it is sent at once, this is only a margin).
            Thread.sleep(100);
        }
        return 0;
    }

    private static String stateLine(Game game) {
        // Without timers: a change of the game, not of the clock.
        String d = game.describe();
        return d.replaceAll(", -?\\d+ s left, secondary -?\\d+ s", "");
    }

    private void status(EmbeddedGameController gc) {
        print("status: " + gc.game().describe());
        print("packets sent: " + gc.sender().packetsSent() + ", send errors: " + gc.sender().sendErrors());
        long now = gc.game().now();
        for (var e : gc.liveness().all(now).entrySet()) {
            RobotLiveness.RobotKey k = e.getKey();
            print("robot " + k + ": " + e.getValue() + ", penalty "
                    + gc.game().snapshot().team(k.team()).player(k.player()).penalty());
        }
        gc.badPackets().bySource().forEach((src, t) ->
                print("bad GameController packets from " + src + ": " + t.count() + " (last: " + t.lastReason() + ")"));
        String warning = gc.rivalWarning();
        if (!warning.isEmpty()) {
            print("! " + warning);
        }
    }

    private GcConfig config(GcProfile profile) {
        List<InetSocketAddress> dests = new ArrayList<>();
        for (String d : destinations) {
            dests.add(parseAddress(d, GcProfile.GAME_STATE_PORT));
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

    static InetSocketAddress parseAddress(String text, int defaultPort) {
        int colon = text.lastIndexOf(':');
        if (colon > 0 && text.indexOf(':') == colon) {
            return new InetSocketAddress(text.substring(0, colon), Integer.parseInt(text.substring(colon + 1)));
        }
        return new InetSocketAddress(text, defaultPort);
    }

    private synchronized void print(String line) {
        out.println(line);
        out.flush();
    }

    /** Stand-alone entry point until {@code touchline.cli.Main} lists this command. */
}
