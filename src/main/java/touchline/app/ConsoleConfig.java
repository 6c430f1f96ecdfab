package touchline.app;

import touchline.transport.UdpConfig;

/**
 * What the application core needs to start.
 *
 * @param udp                 the FUmanoids UDP endpoint
 * @param tickMillis          how often the model checks timeouts and retries
 * @param gameControllerPort  where to listen for the referee's GameController (3838), 0 for not at all
 */
public record ConsoleConfig(UdpConfig udp, long tickMillis, int gameControllerPort) {

    public static ConsoleConfig defaults() {
        return new ConsoleConfig(UdpConfig.defaults(), 100, 3838);
    }

    /** Also stops listening for GameControllers unless the port is set again: tests must not bind fixed ports. */
    public ConsoleConfig withUdp(UdpConfig udp) {
        return new ConsoleConfig(udp, tickMillis, udp.listenPort() == 0 ? 0 : gameControllerPort);
    }

    public ConsoleConfig withGameControllerPort(int port) {
        return new ConsoleConfig(udp, tickMillis, port);
    }
}
