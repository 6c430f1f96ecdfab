package touchline.transport;

import touchline.transport.gamecontroller.GcListener;

import java.io.IOException;
import java.net.InetSocketAddress;

/**
 * Hears the team's own team messages (UDP 10000 + team number, which the robots broadcast to
 * each other) for the budget guard: each datagram becomes an IN {@link Channel#TEAM_MESSAGE}
 * envelope with its sender and its exact size. The content is the team's own format and is not
 * decoded. The port is shared (SO_REUSEADDR), so robots and other consoles on the same host
 * still hear it; datagrams up to 64 KiB arrive whole, so an oversized message is measured, not cut.
 * The port is bound when made; it listens from {@link #start()}.
 */
public final class TeamMessageListener implements AutoCloseable {

    /** The league's team-message ports: 10000 + team number. */
    public static final int BASE_PORT = 10_000;

    private final GcListener listener;

    /**
     * @param bind  usually 0.0.0.0:(10000 + team)
     * @param sink  receives one envelope per team message
     * @param clock time-stamps them
     */
    public TeamMessageListener(InetSocketAddress bind, EnvelopeSink sink, MicrosClock clock) throws IOException {
        this.listener = new GcListener(bind, (data, from) -> sink.accept(new Envelope(clock.nowMicros(), Direction.IN,
                Channel.TEAM_MESSAGE, from, Envelope.NO_ROBOT, "team.message", null, data, null)),
                "team-messages", 65_536);
    }

    /** Starts listening; returns this. */
    public TeamMessageListener start() {
        listener.start();
        return this;
    }

    public static int portOf(int team) {
        return BASE_PORT + team;
    }

    public InetSocketAddress localAddress() throws IOException {
        return listener.localAddress();
    }

    @Override
    public void close() {
        listener.close();
    }
}
