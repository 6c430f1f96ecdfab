package touchline.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.app.Console;
import touchline.model.RobotSnapshot;
import touchline.transport.ReliableSession;

import java.io.InputStream;
import java.util.Optional;
import java.util.concurrent.Callable;

/**
 * Lossless transfer to a robot over the reliable stream: sends standard input, prints what the
 * robot sends back, and returns when everything was acknowledged (and, with --linger, after
 * the robot has been quiet for a while).
 */
@Command(name = "stream", mixinStandardHelpOptions = true,
        description = "Send standard input to a robot over the reliable stream; print what it sends back.")
final class StreamCommand implements Callable<Integer> {

    @Parameters(index = "0", description = "robot ID")
    int robot;

    @Option(names = "--chunk", defaultValue = "512", description = "bytes per segment (1..1398, default ${DEFAULT-VALUE})")
    int chunk;

    @Option(names = "--timeout", defaultValue = "10", description = "seconds to wait for the robot (default ${DEFAULT-VALUE})")
    long timeoutSeconds;

    @Option(names = "--linger", defaultValue = "2", description = "seconds to keep printing after the last acknowledgement")
    long lingerSeconds;

    @Mixin
    UdpOptions udp;

    @Override
    public Integer call() throws Exception {
        try (Console console = udp.startConsole()) {
            Optional<RobotSnapshot> seen = console.field().waitForRobot(robot, java.time.Duration.ofSeconds(timeoutSeconds));
            if (seen.isEmpty()) {
                System.err.println("robot " + robot + " was not seen within " + timeoutSeconds + " s");
                return 2;
            }
            ReliableSession session = console.field().openStream(seen.get().address());
            session.onReceive(p -> {
                System.out.write(p, 0, p.length);
                System.out.flush();
            });
            InputStream in = System.in;
            byte[] buf = new byte[Math.max(1, Math.min(chunk, touchline.protocol.reliable.ReliableStream.MAX_PAYLOAD))];
            long total = 0;
            for (int n = in.read(buf); n > 0; n = in.read(buf)) {
                session.offer(java.util.Arrays.copyOf(buf, n));
                total += n;
            }
            while (!session.idle()) {
                Thread.sleep(20);
            }
            Thread.sleep(lingerSeconds * 1000);
            var stats = session.stats();
            System.err.printf("sent %d bytes in %d segments, %d retransmissions; received %d segments%n", total,
                    stats.dataSent(), stats.retransmissions(), stats.delivered());
            return 0;
        }
    }
}
