package touchline.app;

import touchline.transport.UdpConfig;

/** What the application core needs to start: the UDP endpoint and how often to tick. */
public record ConsoleConfig(UdpConfig udp, long tickMillis) {

    public static ConsoleConfig defaults() {
        return new ConsoleConfig(UdpConfig.defaults(), 100);
    }

    public ConsoleConfig withUdp(UdpConfig udp) {
        return new ConsoleConfig(udp, tickMillis);
    }
}
