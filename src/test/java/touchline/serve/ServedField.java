package touchline.serve;

import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.proto.Fumanoid;
import touchline.protocol.FrameCodec;
import touchline.protocol.Framing;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.Envelope;
import touchline.transport.UdpConfig;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;

/**
 * A console on loopback serving its stream, for the serve tests: robots send real datagrams
 * to it ({@link #send}), or envelopes go straight into its bus ({@link #publish}) where a test
 * needs to know exactly what was ingested.
 */
final class ServedField implements AutoCloseable {

    private final FrameCodec frames = new FrameCodec();
    private final Console console;
    private final FoxgloveServer server;
    private final AutoCloseable subscription;
    private final DatagramSocket robot;

    ServedField(ServeConfig config) throws Exception {
        console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start();
        server = new FoxgloveServer(config, console.field().kinds(), console.field().clock()).start();
        console.serving().stateChannels().forEach(server::serveJson); // as Serving does
        subscription = console.field().bus().subscribe(server);
        robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
    }

    ServedField() throws Exception {
        this(ServeConfig.defaults().withPort(0));
    }

    FoxgloveServer server() {
        return server;
    }

    Console console() {
        return console;
    }

    static Fumanoid.Message status(int robotId, String name, int battery) {
        return Fumanoid.Message.newBuilder().setRobotID(robotId).setExtension(Fumanoid.status,
                Fumanoid.Status.newBuilder().setRobotName(name).setBatteryPercent(battery).setTeamID(13).build()).build();
    }

    static Fumanoid.Message text(int robotId, String option, String text) {
        return Fumanoid.Message.newBuilder().setRobotID(robotId).setExtension(Fumanoid.debugText,
                Fumanoid.DebugText.newBuilder().setOption(option).setText(text).build()).build();
    }

    /** A robot's datagram to the console's UDP port. */
    void send(Fumanoid.Message m) throws Exception {
        byte[] d = frames.encode(Framing.LENGTH_PREFIX, m.toByteArray());
        robot.send(new DatagramPacket(d, d.length, InetAddress.getLoopbackAddress(), console.field().port()));
    }

    /** Publishes {@code m} into the console's Envelope stream as if its robot had sent it; returns when every subscriber has it. */
    void publish(Fumanoid.Message m, String kind) {
        console.field().bus().accept(new Envelope(console.field().clock().nowMicros(), Direction.IN, Channel.FUMANOID,
                new InetSocketAddress("127.0.0.1", 40000 + m.getRobotID()), m.getRobotID(), kind, m,
                frames.encode(Framing.LENGTH_PREFIX, m.toByteArray()), null));
    }

    /**
     * As {@link #publish}, but the datagram as a robot with a team key sends it: with the 32-byte
     * trailer behind the frame, as the console's decoder hands it on once the tag checked out.
     */
    void publishTagged(Fumanoid.Message m, String kind, long counter) {
        byte[] tagged = new touchline.security.MessageTag(new touchline.security.TeamKey(new byte[32])).append(
                touchline.security.MessageTag.FROM_ROBOT, m.getRobotID(), counter,
                frames.encode(Framing.LENGTH_PREFIX, m.toByteArray()));
        console.field().bus().accept(new Envelope(console.field().clock().nowMicros(), Direction.IN, Channel.FUMANOID,
                new InetSocketAddress("127.0.0.1", 40000 + m.getRobotID()), m.getRobotID(), kind, m, tagged, null,
                touchline.transport.Origin.LIVE, touchline.security.Authenticity.VERIFIED));
    }

    /** A GameController packet from the golden files (e.g. {@code hl12/04-playing.bin}) into the stream, as heard on 3838. */
    void publishGameState(String golden) throws Exception {
        byte[] packet;
        try (var in = ServedField.class.getResourceAsStream("/golden/gamecontroller/" + golden)) {
            packet = in.readAllBytes();
        }
        console.field().bus().accept(new Envelope(console.field().clock().nowMicros(), Direction.IN, Channel.GAMECONTROLLER,
                new InetSocketAddress("127.0.0.1", 3838), Envelope.NO_ROBOT, "gc.hl12", null, packet, null));
    }

    @Override
    public void close() throws Exception {
        subscription.close();
        server.close();
        console.close();
        robot.close();
    }
}
