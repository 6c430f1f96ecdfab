package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.record.RecordingException;
import touchline.serve.AccessToken;
import touchline.serve.AllowedOrigins;
import touchline.serve.FoxgloveServer;
import touchline.serve.ServeConfig;
import touchline.serve.ServeStats;
import touchline.serve.ViewerInfo;
import touchline.transport.UdpConfig;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * {@code touchline serve}: listens for the robots like {@code listen} and serves the stream live
 * to Foxglove, Lichtblick or any Foxglove WebSocket client, printing the viewers, their
 * subscriptions, rates and drops every few seconds. Loopback only unless a token protects it.
 */
@Command(name = "serve", mixinStandardHelpOptions = true,
        description = "Listen for robots and serve their messages live to Foxglove/Lichtblick viewers (Foxglove WebSocket).")
final class ServeCommand implements Callable<Integer> {

    @Option(names = "--port", defaultValue = "8765", description = "WebSocket port viewers connect to (default ${DEFAULT-VALUE})")
    int port;

    @Option(names = "--bind", defaultValue = "127.0.0.1",
            description = "address to serve on (default ${DEFAULT-VALUE}: this machine only; any other needs a token)")
    String bind;

    @Option(names = "--token", description = "the token viewers must present (generated when serving beyond loopback"
            + " without one); visible to others in the process list: prefer --token-file or $" + TokenChoice.ENV)
    String token;

    @Option(names = "--token-file", paramLabel = "FILE",
            description = "read the token from the first line of FILE (mode 0600: only you may read it)")
    Path tokenFile;

    @Option(names = "--allow-origin", paramLabel = "ORIGIN",
            description = "a web page origin that may watch too, e.g. https://viewer.example.org (repeatable);"
                    + " allowed without it: tools (no origin), https://app.foxglove.dev, Lichtblick's web build")
    java.util.List<String> allowOrigins = new java.util.ArrayList<>();

    @Option(names = "--robots-port", defaultValue = "11011", description = "UDP port robots send to (default ${DEFAULT-VALUE})")
    int robotsPort;

    @Option(names = "--robots-bind", defaultValue = "0.0.0.0", description = "address to hear robots on (default ${DEFAULT-VALUE})")
    String robotsBind;

    @picocli.CommandLine.Mixin
    TeamBudgetOptions budget;

    @Option(names = "--proto", paramLabel = "FILE", description = "a team's protoc descriptor set: its messages are served with their own types")
    Path proto;

    @Option(names = "--record", paramLabel = "FILE", description = "record to this MCAP file beside serving")
    Path record;

    @Option(names = "--stats-every", defaultValue = "5", description = "seconds between statistics lines (default ${DEFAULT-VALUE})")
    long statsEvery;

    @Option(names = "--seconds", description = "stop after this many seconds (default: until Ctrl+C)")
    long seconds;

    @Option(names = "--tls-cert", paramLabel = "FILE", description = "serve wss:// with this PEM certificate (with --tls-key)")
    Path tlsCert;

    @Option(names = "--tls-key", paramLabel = "FILE", description = "the certificate's PEM private key (PKCS#8, no password)")
    Path tlsKey;

    @Option(names = "--keys", paramLabel = "DIR",
            description = "the team's key directory (default: $TOUCHLINE_KEYS, else ~/.config/touchline/keys when it"
                    + " holds team.key): tags every datagram to the small robots, checks theirs (docs/security.md);"
                    + " not used with FILE.mcap")
    Path keys;

    @Option(names = "--insecure", description = "no team key even if one is there: nothing tagged or checked, for"
            + " robots without keys (lab mode)")
    boolean insecure;

    @CommandLine.Parameters(arity = "0..1", paramLabel = "FILE.mcap",
            description = "serve a recording instead of the field (played through the replay pipeline: "
                    + "nothing goes to robots, no UDP port is taken)")
    Path replayFile;

    @Option(names = "--speed", defaultValue = "1", description = "with FILE.mcap: playback speed (default ${DEFAULT-VALUE})")
    double speed;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        String given;
        try {
            given = new TokenChoice(token, tokenFile, System.getenv()).token();
        } catch (StartFailure e) {
            err.println("touchline serve: " + e.getMessage());
            return e.exitCode();
        }
        ServeConfig config = ServeConfig.defaults().withBind(bind).withPort(port).withToken(given)
                .withOrigins(new AllowedOrigins(allowOrigins));
        if (given == null && !config.loopbackOnly()) {
            config = config.withToken(AccessToken.generate(new SecureRandom()));
        }
        if ((tlsCert == null) != (tlsKey == null)) {
            err.println("touchline serve: TLS needs both --tls-cert and --tls-key");
            return 2;
        }
        if (tlsCert != null) {
            config = config.withTls(tlsCert, tlsKey);
        }
        CountDownLatch stop = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(stop::countDown));
        ConsoleConfig consoleConfig;
        try {
            consoleConfig = replayFile != null
                    // a replay is all that is served: no robot port taken, no GameController heard
                    ? ConsoleConfig.defaults().withGameControllerPort(0)
                            .withUdp(UdpConfig.defaults().withListenPort(0).withBindAddress("127.0.0.1"))
                    : ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withListenPort(robotsPort)
                            .withBindAddress(robotsBind)).withSecurity(new KeyChoice(keys, insecure, System.getenv()).security());
        } catch (StartFailure e) {
            err.println("touchline serve: " + e.getMessage());
            return e.exitCode();
        }
        try (Console console = new Console(consoleConfig)) {
            if (proto != null) {
                try {
                    console.teamSchemas().load(proto).refusals().forEach(r -> err.println("touchline serve: " + r));
                } catch (RecordingException e) {
                    err.println("touchline serve: " + e.getMessage());
                    return 2;
                }
            }
            FoxgloveServer server; // stopped first when the console closes
            try {
                // a replay never acts on the field: viewers switch options only on a live one (`options --connect`)
                server = replayFile == null ? console.serving().start(config) : console.serving().startReplay(config);
            } catch (IllegalArgumentException e) {
                err.println("touchline serve: " + e.getMessage());
                return 2;
            } catch (Exception e) {
                if (StartFailure.addressInUse(e)) {
                    return say(err, StartFailure.portInUse("WebSocket", port, "viewers", bind, "--port"));
                }
                err.println("touchline serve: cannot serve on " + bind + ":" + port + ": " + e.getMessage());
                return 1;
            }
            try {
                console.start();
            } catch (Exception e) { // Netty rethrows the native bind error undeclared
                if (StartFailure.addressInUse(e)) {
                    return say(err, StartFailure.portInUse("UDP", robotsPort, "robots", robotsBind, "--robots-port"));
                }
                throw e;
            }
            new FirstListenLines(err, "serve").follow(console.referee().matchMode());
            if (replayFile != null) {
                console.field().setLiveListening(false);
                try {
                    var replay = console.replays().open(replayFile);
                    replay.setSpeed(speed);
                    replay.play();
                    replay.problems().forEach(p -> err.println("touchline serve: " + replayFile + ": " + p));
                } catch (RecordingException e) {
                    err.println("touchline serve: " + e.getMessage());
                    return 2;
                }
                out.println("serving the recording " + replayFile.toAbsolutePath() + " at speed " + speed);
            } else {
                if (record != null) {
                    console.recordings().start(record);
                }
                try {
                    budget.guard(console.teamBudget(), robotsBind); // served as /team/budget with --team
                } catch (StartFailure e) {
                    err.println("touchline serve: " + e.getMessage());
                    return e.exitCode();
                }
                out.println("hearing robots on UDP port " + console.field().port()
                        + (record == null ? "" : ", recording to " + record.toAbsolutePath()));
            }
            out.println("serving Foxglove WebSocket (Foxglove/Lichtblick: Open connection → Foxglove WebSocket):");
            for (String url : server.urls()) {
                out.println("  " + url);
            }
            out.flush();
            watch(server, stop, out);
        }
        return 0;
    }

    private static int say(PrintWriter err, StartFailure f) {
        err.println("touchline serve: " + f.getMessage());
        err.flush();
        return f.exitCode();
    }

    private void watch(FoxgloveServer server, CountDownLatch stop, PrintWriter out) throws InterruptedException {
        long deadline = seconds > 0 ? System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds) : Long.MAX_VALUE;
        ServeStats last = server.stats();
        long lastAt = System.nanoTime();
        while (true) {
            long wait = Math.min(TimeUnit.SECONDS.toNanos(Math.max(1, statsEvery)), deadline - System.nanoTime());
            boolean stopped = wait <= 0 || stop.await(wait, TimeUnit.NANOSECONDS);
            ServeStats now = server.stats();
            long at = System.nanoTime();
            double secs = Math.max(1e-3, (at - lastAt) / 1e9);
            out.printf("viewers %d, subscriptions %d, channels %d, sent %d (%.0f/s), dropped %d (%.0f/s), "
                            + "%s%s, bad requests %d%s%n", now.viewers(), now.subscriptions(), now.channels(),
                    now.sent(), (now.sent() - last.sent()) / secs, now.dropped(), (now.dropped() - last.dropped()) / secs,
                    now.refusedInWords(), now.upgrading() == 0 ? "" : ", upgrading " + now.upgrading(), now.badRequests(),
                    (now.channelsRefused() == 0 ? "" : ", channels not served (table full) " + now.channelsRefused())
                            + (now.notConverted() == 0 ? "" : ", not converted to standard channels (behind) "
                            + now.notConverted()));
            for (ViewerInfo v : server.viewers()) {
                out.printf("  viewer %s: %d subscriptions, sent %d, dropped %d%n", v.address(), v.topics().size(),
                        v.sent(), v.dropped());
            }
            out.flush();
            last = now;
            lastAt = at;
            if (stopped) {
                return;
            }
        }
    }
}
