package touchline.transport;

/**
 * Where the console listens and how it reaches robots.
 *
 * @param bindAddress    local address to bind, e.g. {@code 0.0.0.0} on a field, {@code 127.0.0.1} in tests
 * @param listenPort     the console port robots send to (11011), or 0 for one chosen by the OS
 * @param robotPort      the port robots listen on (3838), or 0 to answer each robot at its datagram's source port
 * @param receiveBuffer  socket receive buffer in bytes (large enough for bursts of 50 000 messages/s)
 * @param transport      the Netty transport asked for: auto, epoll-mmsg, epoll or nio ({@link UdpBackend})
 */
public record UdpConfig(String bindAddress, int listenPort, int robotPort, int receiveBuffer, String transport) {

    public static final int CONSOLE_PORT = 11011;
    public static final int ROBOT_PORT = 3838;

    public static UdpConfig defaults() {
        return new UdpConfig("0.0.0.0", CONSOLE_PORT, 0, 8 << 20,
                System.getProperty(UdpBackend.PROPERTY, UdpBackend.AUTO));
    }

    public UdpConfig withListenPort(int port) {
        return new UdpConfig(bindAddress, port, robotPort, receiveBuffer, transport);
    }

    public UdpConfig withBindAddress(String address) {
        return new UdpConfig(address, listenPort, robotPort, receiveBuffer, transport);
    }

    public UdpConfig withRobotPort(int port) {
        return new UdpConfig(bindAddress, listenPort, port, receiveBuffer, transport);
    }

    public UdpConfig withTransport(String requested) {
        return new UdpConfig(bindAddress, listenPort, robotPort, receiveBuffer, requested);
    }
}
