package touchline.bench;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import touchline.security.MessageTag;
import touchline.security.TeamKey;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

/**
 * The cost of one datagram's tag (issue 15): {@link MessageTag} (trailer version 2,
 * HMAC-SHA-256 on one reused JDK {@code Mac}) against version 1's tag, the JDK's {@code Mac}
 * "HmacSHA512" over the same bytes, alternating in one run over the ingest benchmark's
 * six-robot datagrams. One thread, no I/O.
 */
@Command(name = "tag", mixinStandardHelpOptions = true,
        description = "Nanoseconds per datagram tag: the tag (HMAC-SHA-256) against version 1's HMAC-SHA-512, alternating rounds.")
final class TagBenchCommand implements Callable<Integer> {

    @Option(names = "--rounds", defaultValue = "5", description = "alternating rounds (default ${DEFAULT-VALUE})")
    int rounds;

    @Option(names = "--seconds", defaultValue = "2", description = "seconds per measurement (default ${DEFAULT-VALUE})")
    double seconds;

    private final List<byte[]> datagrams = new IngestTraffic().sixRobots(1);
    private final byte[] key = new byte[TeamKey.SIZE];
    /** Each round's outputs folded together, printed, so the JIT cannot drop the work. */
    private long sink;

    @Override
    public Integer call() throws Exception {
        MessageTag ours = new MessageTag(new TeamKey(key));
        Mac jdk = Mac.getInstance("HmacSHA512");
        jdk.init(new SecretKeySpec(key, "HmacSHA512"));
        byte[] head = new byte[2 + TeamKey.ID_SIZE + 8];
        System.out.printf("tag benchmark: %d rounds x %.1f s each, %d datagrams of %d..%d bytes%n", rounds, seconds,
                datagrams.size(), datagrams.stream().mapToInt(d -> d.length).min().orElse(0),
                datagrams.stream().mapToInt(d -> d.length).max().orElse(0));
        for (int warm = 0; warm < 2; warm++) {
            perDatagram(() -> jdkTag(jdk, head));
            perDatagram(() -> ourTag(ours));
        }
        List<Double> ratios = new ArrayList<>();
        for (int round = 1; round <= rounds; round++) {
            double mac = perDatagram(() -> jdkTag(jdk, head));
            double tag = perDatagram(() -> ourTag(ours));
            ratios.add(mac / tag);
            System.out.printf("round %d: version 1 (HmacSHA512) %.0f ns, MessageTag (HmacSHA256) %.0f ns per datagram:"
                    + " %.2f x as fast%n",
                    round, mac, tag, mac / tag);
        }
        System.out.printf("median: MessageTag %.2f x as fast as version 1's HmacSHA512 (checksum %d)%n",
                IngestBenchCommand.median(ratios), sink);
        return 0;
    }

    private long counter;

    private void ourTag(MessageTag tag) {
        byte[] d = datagrams.get((int) (counter % datagrams.size()));
        sink += tag.tag(MessageTag.FROM_ROBOT, 3, ++counter, d, 0, d.length)[0];
    }

    private void jdkTag(Mac mac, byte[] head) {
        byte[] d = datagrams.get((int) (counter % datagrams.size()));
        head[0] = MessageTag.FROM_ROBOT.direction();
        head[1] = 3;
        head[13] = (byte) ++counter;
        mac.update(head);
        mac.update(d, 0, d.length);
        sink += mac.doFinal()[0];
    }

    /** Nanoseconds per call of {@code one}, over about {@link #seconds}. */
    private double perDatagram(Runnable one) {
        return nanosPerCall(one, seconds);
    }

    /** Nanoseconds per call of {@code one}, calling it for about {@code seconds} (also the CDR benchmark's measure). */
    static double nanosPerCall(Runnable one, double seconds) {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        long calls = 0;
        long start = System.nanoTime();
        long now;
        do {
            for (int i = 0; i < 1000; i++) {
                one.run();
            }
            calls += 1000;
        } while ((now = System.nanoTime()) < end);
        return (now - start) / (double) calls;
    }
}
