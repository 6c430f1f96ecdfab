package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.app.Console;
import touchline.app.Naos;
import touchline.app.Referee;
import touchline.app.ConsoleConfig;
import touchline.app.NaoCamera;
import touchline.app.NaoFrame;
import touchline.app.NaoSession;
import touchline.app.game.MatchMode;
import touchline.protocol.nao.NaoModules;
import touchline.protocol.nao.ParamSyntax;
import touchline.transport.HostPort;
import touchline.transport.nao.CallOutcome;
import touchline.transport.nao.CameraSettings;
import touchline.transport.nao.ConnectionState;
import touchline.security.KeyException;
import touchline.transport.nao.NaoClientKeys;
import touchline.transport.nao.NaoCall;
import touchline.transport.nao.NaoLinkConfig;
import touchline.transport.UdpConfig;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;

/**
 * {@code touchline nao ...}: drive a NAO (or the simulated one) from the command line through
 * the application core, as the window does: {@code call} and {@code methods} start a
 * {@link Console} that listens for the field's GameController and open a {@link NaoSession}
 * on it, so during play every call is held back by match mode and nothing reaches the robot.
 * {@code call} invokes any NAOqi method with typed parameters (see {@link ParamSyntax}),
 * {@code methods} lists what each module offers, {@code cam} saves one camera frame (a
 * console's {@link NaoCamera}, the frame read from its stream as the window's view reads it;
 * fetching frames sends the robot no command, so it is not held). Exit code 0 on success, 1
 * when the robot answered with an error or could not be reached, 2 on a usage error, 3 when
 * match mode held the call back.
 */
@Command(name = "nao", mixinStandardHelpOptions = true,
        description = "Call NAOqi methods and fetch camera frames from a NAO (RPC port 5555, camera 5556), "
                + "encrypted with CURVE keys (--keys DIR) unless --insecure.",
        subcommands = {NaoCommand.Call.class, NaoCommand.Methods.class, NaoCommand.Cam.class})
public final class NaoCommand implements Runnable {

    static final int RPC_PORT = 5555;
    static final int HELD_BACK = 3;
    static final int CAM_PORT = 5556;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }


    abstract static class LinkOptions {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;

        @CommandLine.Mixin
        NaoKeyOptions security;

        @Option(names = "--config", description = "link rules (timeouts, intervals, idempotent methods), e.g. samples/nao.properties")
        Path config;

        @Option(names = "--connect-timeout", defaultValue = "3000", description = "ms to wait for the robot (default ${DEFAULT-VALUE})")
        long connectTimeoutMs;

        @Option(names = "--gc-port", defaultValue = "3838",
                description = "where to hear the field's GameController: during play every call is held back "
                        + "(match mode); 0: do not listen (default ${DEFAULT-VALUE})")
        int gcPort;

        @Option(names = "--gc-address", paramLabel = "HOST",
                description = "believe game states only from this GameController (default: the first heard)")
        String gcAddress;

        @Option(names = "--listen", paramLabel = "MS", defaultValue = "0",
                description = "listen at least this long for a GameController before the first call (default: match"
                        + " mode's first listen, up to " + MatchMode.LISTEN_FIRST_MS + " ms, over as soon as a"
                        + " GameController says play is off)")
        long listenMs;

        /** The application core the calls go through: it only listens (GameController port, no robot port). */
        Console startConsole() throws InterruptedException {
            ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withListenPort(0))
                    .withGameControllerPort(gcPort).withGcAddress(gcAddress);
            Console console = new Console(config).start();
            new FirstListenLines(err(), "nao").follow(console.referee().matchMode());
            return console;
        }

        /** Prints the outcome; the exit code for it. */
        int report(CallOutcome outcome) {
            (outcome.ok() ? out() : err()).println(outcome.describe());
            return outcome.ok() ? 0 : outcome instanceof CallOutcome.HeldBack ? HELD_BACK : 1;
        }

        NaoLinkConfig loadConfig() {
            if (config == null) {
                return NaoLinkConfig.defaults();
            }
            NaoLinkConfig c = NaoLinkConfig.load(config);
            for (String problem : c.problems()) {
                err().println("warning: " + problem);
            }
            return c;
        }

        PrintWriter out() {
            return spec.commandLine().getOut();
        }

        PrintWriter err() {
            return spec.commandLine().getErr();
        }

        /**
         * A session through {@code naos}, online, once {@code referee} has listened for a GameController;
         * null (after printing why) when the address or the keys are unusable or the robot did not
         * come online in time.
         */
        NaoSession connect(Naos naos, Referee referee, String target, int defaultPort) throws InterruptedException {
            HostPort t;
            try {
                t = HostPort.parse(target, defaultPort);
            } catch (IllegalArgumentException e) {
                err().println(e.getMessage());
                return null;
            }
            NaoClientKeys keys;
            try {
                keys = security.load();
            } catch (KeyException e) {
                err().println(e.getMessage());
                return null;
            }
            NaoSession link = naos.connect(t.host(), t.port(), 0, keys, loadConfig());
            long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(connectTimeoutMs);
            while (link.state() != ConnectionState.ONLINE && link.state() != ConnectionState.REFUSED
                    && System.nanoTime() < end) {
                Thread.sleep(10);
            }
            if (link.state() == ConnectionState.REFUSED) {
                err().println(t.host() + ":" + t.port() + ": " + link.securityProblem());
                link.close();
                return null;
            }
            if (link.state() != ConnectionState.ONLINE) {
                err().println("no NAO RPC module answering at " + t.host() + ":" + t.port()
                        + " within " + connectTimeoutMs + " ms" + (keys == null
                        ? " (insecure: a NAO that runs with CURVE keys does not answer an insecure console; "
                          + "without --insecure the keys are used — see docs/security.md)" : ""));
                link.close();
                return null;
            }
            // A console that just opened the GameController port listens for one first (match mode):
            // the call waits for that (at least --listen), or for play to be heard, instead of being held for it.
            referee.awaitFirstListen(listenMs, java.time.Duration.ofMillis(Math.max(listenMs, MatchMode.LISTEN_FIRST_MS) + 1000));
            return link;
        }
    }

    @Command(name = "call", mixinStandardHelpOptions = true,
            description = "Call Module.method with parameters: 42 int, 0.5 float, true, [a, 1], \"42\" string, other text string.")
    static final class Call extends LinkOptions implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "HOST[:PORT]")
        String target;
        @Parameters(index = "1", paramLabel = "Module.method")
        String method;
        @Parameters(index = "2..*", paramLabel = "PARAM")
        List<String> params = new ArrayList<>();
        @Option(names = "--timeout", description = "ms before the call counts as timed out (default: from the config)")
        Long timeoutMs;

        @Override
        public Integer call() throws Exception {
            NaoCall call;
            try {
                List<Object> values = new ArrayList<>();
                for (String p : params) {
                    values.add(ParamSyntax.parse(p));
                }
                call = NaoCall.parse(method, values);
            } catch (IllegalArgumentException e) {
                err().println(e.getMessage());
                return 2;
            }
            try (Console console = startConsole(); NaoSession link = connect(console.naos(), console.referee(), target, RPC_PORT)) {
                if (link == null) {
                    return 1;
                }
                long timeout = timeoutMs != null ? timeoutMs : link.config().timeoutMillis(call);
                return report(link.call(call, timeout).get());
            }
        }
    }

    @Command(name = "methods", mixinStandardHelpOptions = true,
            description = "List the methods of each module (getMethodList); default: the standard NAOqi modules.")
    static final class Methods extends LinkOptions implements Callable<Integer> {
        @Parameters(index = "0", paramLabel = "HOST[:PORT]")
        String target;
        @Parameters(index = "1..*", paramLabel = "MODULE")
        List<String> modules = new ArrayList<>();

        @Override
        public Integer call() throws Exception {
            try (Console console = startConsole(); NaoSession link = connect(console.naos(), console.referee(), target, RPC_PORT)) {
                if (link == null) {
                    return 1;
                }
                int failures = 0;
                boolean held = false;
                for (String module : modules.isEmpty() ? NaoModules.NAOQI : modules) {
                    CallOutcome outcome = link.call(NaoCall.of(module, "getMethodList")).get();
                    if (outcome instanceof CallOutcome.Value v && v.value() instanceof List<?> names) {
                        out().println(module + ": " + String.join(" ", names.stream().map(String::valueOf).toList()));
                    } else {
                        failures++;
                        held |= outcome instanceof CallOutcome.HeldBack;
                        err().println(module + ": " + outcome.describe());
                    }
                }
                return failures == 0 ? 0 : held ? HELD_BACK : 1;
            }
        }
    }

    @Command(name = "cam", mixinStandardHelpOptions = true, description = "Configure the camera and save one JPEG frame.")
    static final class Cam implements Callable<Integer> {
        @CommandLine.Spec
        CommandLine.Model.CommandSpec spec;
        @CommandLine.Mixin
        NaoKeyOptions security;
        @Parameters(index = "0", paramLabel = "HOST[:PORT]")
        String target;
        @Option(names = "--save", required = true, description = "where to write the JPEG")
        Path save;
        @Option(names = "--resolution", defaultValue = "2", description = "0 160x120, 1 320x240, 2 640x480, 3 1280x960 (default ${DEFAULT-VALUE})")
        int resolution;
        @Option(names = "--color-space", defaultValue = "11", description = "0 kYuv, 9 kYUV422, 10 kYUV, 11 kRGB, 12 kHSY, 13 kBGR (default ${DEFAULT-VALUE})")
        int colorSpace;
        @Option(names = "--fps", defaultValue = "15", description = "1..30 (default ${DEFAULT-VALUE})")
        int fps;
        @Option(names = "--timeout", defaultValue = "5000", description = "ms to wait for a frame (default ${DEFAULT-VALUE})")
        long timeoutMs;

        @Override
        public Integer call() throws Exception {
            CameraSettings settings;
            HostPort t;
            NaoClientKeys keys;
            try {
                settings = new CameraSettings(resolution, colorSpace, fps);
                t = HostPort.parse(target, CAM_PORT);
            } catch (IllegalArgumentException e) {
                spec.commandLine().getErr().println(e.getMessage());
                return 2;
            }
            try {
                keys = security.load();
            } catch (KeyException e) {
                spec.commandLine().getErr().println(e.getMessage());
                return 1;
            }
            // a console that listens for nothing (no robot port, no GameController): the camera's frames only
            ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withListenPort(0))
                    .withGameControllerPort(0);
            try (Console console = new Console(config).start();
                 NaoCamera camera = console.naos().connectCamera(t.host(), t.port(), keys)) {
                camera.configure(settings);
                camera.watch(true);
                long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
                while (console.naos().camera().latest().isEmpty() && System.nanoTime() < end) {
                    Thread.sleep(10);
                }
                camera.watch(false);
                if (console.naos().camera().latest().isEmpty()) {
                    spec.commandLine().getErr().println("no frame from " + t.host() + ":" + t.port() + " within "
                            + timeoutMs + " ms" + (camera.problem().isEmpty() ? "" : ": " + camera.problem()));
                    return 1;
                }
                NaoFrame frame = console.naos().camera().latest().get();
                Files.write(save, frame.jpeg());
                spec.commandLine().getOut().println("saved " + save + ": " + frame.width() + "x" + frame.height()
                        + ", " + frame.jpeg().length + " bytes");
                return 0;
            }
        }
    }
}
