package touchline.cli;

import picocli.CommandLine.Option;
import touchline.app.ConsoleConfig;
import touchline.protocol.gamecontroller.MonitorRequest;
import touchline.security.LinkSecurity;
import touchline.transport.UdpConfig;

import java.net.InetSocketAddress;

/** The network options every listening command shares. */
final class UdpOptions {

    @Option(names = "--port", description = "UDP port robots send to (default ${DEFAULT-VALUE})", defaultValue = "11011")
    int port;

    @Option(names = "--bind", description = "local address to listen on (default ${DEFAULT-VALUE})", defaultValue = "0.0.0.0")
    String bind;

    @Option(names = "--robot-port", defaultValue = "0",
            description = "port robots listen on (3838 on a field); 0 answers each robot at its source port (default)")
    int robotPort;

    @Option(names = "--gc-monitor", paramLabel = "HOST",
            description = "register as a monitor with the field's HSL GameController at HOST: its true game state "
                    + "and the robots' return packets as it sees them (it refuses hosts that send return packets)")
    String gcMonitor;

    @Option(names = "--gc-address", paramLabel = "HOST",
            description = "the field's GameController: believe game states only from HOST (default: the first "
                    + "GameController heard); any other source is shown as a warning")
    String gcAddress;

    @Option(names = "--gc-forward-port", defaultValue = "3940",
            description = "port the GameController forwards return packets to (default ${DEFAULT-VALUE})")
    int gcForwardPort;

    @Option(names = "--transport", paramLabel = "auto|epoll-mmsg|epoll|nio", converter = TransportName.class,
            defaultValue = "${sys:touchline.udp:-auto}",
            description = "the UDP transport: auto (default) takes epoll with recvmmsg on Linux and NIO, the portable "
                    + "fallback, elsewhere; the choice is printed at start and shown in the window")
    String transport;

    /** Checks the name when the command line is parsed: a wrong one is a usage error, not a crash. */
    static final class TransportName implements picocli.CommandLine.ITypeConverter<String> {
        @Override
        public String convert(String value) {
            try {
                touchline.transport.UdpBackend.choose(value, true, "");
                return value;
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    @Option(names = "--keys", paramLabel = "DIR",
            description = "the team's key directory (default: $TOUCHLINE_KEYS, else ~/.config/touchline/keys when it"
                    + " holds team.key): tags every datagram to the small robots, checks theirs (docs/security.md)")
    java.nio.file.Path keys;

    @Option(names = "--insecure", description = "no team key even if one is there: nothing tagged or checked, for"
            + " robots without keys (lab mode)")
    boolean insecure;

    /** A started Console on these options; a port in use fails with one sentence naming it. */
    touchline.app.Console startConsole() throws InterruptedException, StartFailure {
        touchline.app.Console console = new touchline.app.Console(config());
        try {
            return start(console);
        } catch (InterruptedException | StartFailure | RuntimeException e) {
            console.close();
            throw e;
        }
    }

    /** Starts {@code console}, made on these options; a port in use fails with one sentence naming it. */
    touchline.app.Console start(touchline.app.Console console) throws InterruptedException, StartFailure {
        try {
            return console.start();
        } catch (Exception e) { // Netty rethrows the native bind error undeclared
            if (StartFailure.addressInUse(e)) {
                throw StartFailure.robotsPortInUse(bind, port);
            }
            throw e;
        }
    }

    /** The team key as these options and the environment say; a bad key file fails with its message. */
    LinkSecurity security() throws StartFailure {
        return new KeyChoice(keys, insecure, System.getenv()).security();
    }

    /** The console's configuration on these options, with the team key they choose. */
    ConsoleConfig config() throws StartFailure {
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withListenPort(port)
                .withBindAddress(bind).withRobotPort(robotPort).withTransport(transport)).withSecurity(security());
        config = config.withGcAddress(gcAddress);
        return gcMonitor == null ? config
                : config.withGcMonitor(new InetSocketAddress(gcMonitor, MonitorRequest.PORT), gcForwardPort);
    }
}
