package touchline.app;

import touchline.protocol.gamecontroller.ForwardedReturnPacket;
import touchline.security.LinkSecurity;
import touchline.transport.UdpConfig;

import java.net.InetSocketAddress;

/**
 * What the application core needs to start.
 *
 * @param udp                 the FUmanoids UDP endpoint
 * @param tickMillis          how often the model checks timeouts and retries
 * @param gameControllerPort  where to listen for the referee's GameController (3838), 0 for not at all
 * @param gcMonitor           the field's HSL GameController to register with as a monitor
 *                            ({@code --gc-monitor HOST}, its port 3636), or null
 * @param gcForwardPort       where that GameController forwards the robots' return packets (3940)
 * @param gcAddress           the field's GameController's host ({@code --gc-address}): the only source of
 *                            game states believed; null pins the first heard (or the {@code gcMonitor} host)
 * @param security            the team key for the small robots' link, or off (lab mode)
 */
public record ConsoleConfig(UdpConfig udp, long tickMillis, int gameControllerPort, InetSocketAddress gcMonitor,
                            int gcForwardPort, String gcAddress, LinkSecurity security) {

    public ConsoleConfig(UdpConfig udp, long tickMillis, int gameControllerPort) {
        this(udp, tickMillis, gameControllerPort, null, ForwardedReturnPacket.PORT);
    }

    public ConsoleConfig(UdpConfig udp, long tickMillis, int gameControllerPort, InetSocketAddress gcMonitor,
                         int gcForwardPort) {
        this(udp, tickMillis, gameControllerPort, gcMonitor, gcForwardPort, null, LinkSecurity.off());
    }

    /** Believes game states only from {@code host} (an IP address or name), null: the first heard. */
    public ConsoleConfig withGcAddress(String host) {
        return new ConsoleConfig(udp, tickMillis, gameControllerPort, gcMonitor, gcForwardPort, host, security);
    }

    /** Tags what goes to the small robots and checks what they send with this team key (or not: off). */
    public ConsoleConfig withSecurity(LinkSecurity security) {
        return new ConsoleConfig(udp, tickMillis, gameControllerPort, gcMonitor, gcForwardPort, gcAddress, security);
    }

    public static ConsoleConfig defaults() {
        return new ConsoleConfig(UdpConfig.defaults(), 100, 3838);
    }

    /** Also stops listening for GameControllers unless the port is set again: tests must not bind fixed ports. */
    public ConsoleConfig withUdp(UdpConfig udp) {
        return new ConsoleConfig(udp, tickMillis, udp.listenPort() == 0 ? 0 : gameControllerPort, gcMonitor,
                gcForwardPort, gcAddress, security);
    }

    public ConsoleConfig withGameControllerPort(int port) {
        return new ConsoleConfig(udp, tickMillis, port, gcMonitor, gcForwardPort, gcAddress, security);
    }

    /** Registers with this GameController (monitor requests to {@code gameController}, forwards on {@code forwardPort}). */
    public ConsoleConfig withGcMonitor(InetSocketAddress gameController, int forwardPort) {
        return new ConsoleConfig(udp, tickMillis, gameControllerPort, gameController, forwardPort, gcAddress, security);
    }
}
