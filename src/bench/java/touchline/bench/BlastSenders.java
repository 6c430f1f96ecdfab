package touchline.bench;

import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The ingest benchmark's {@code --flood} load: {@code touchline-blast} processes (C,
 * sendmmsg) sending as fast as they can, each its own six robots (a robot keeps its address).
 */
final class BlastSenders {

    private final Path bin;
    private final List<Path> datagramFiles = new ArrayList<>();

    /** Writes one file of datagrams per sender (deleted when the JVM exits). */
    BlastSenders(Path bin, int count, IngestTraffic traffic) throws IOException {
        this.bin = bin;
        for (int i = 0; i < count; i++) {
            Path file = Files.createTempFile("touchline-ingest", ".bin");
            file.toFile().deleteOnExit();
            try (DataOutputStream out = new DataOutputStream(Files.newOutputStream(file))) {
                for (byte[] d : traffic.sixRobots(1 + 6 * i)) {
                    out.writeShort(d.length);
                    out.write(d);
                }
            }
            datagramFiles.add(file);
        }
    }

    IngestResult send(int port, int secs, DecodedCounter decoded) throws Exception {
        long startCount = decoded.sum();
        List<Process> senders = new ArrayList<>();
        for (java.nio.file.Path file : datagramFiles) {
            senders.add(new ProcessBuilder(bin.toString(), "--to", "127.0.0.1:" + port, "--file",
                    file.toString(), "--seconds", Integer.toString(secs))
                    .redirectError(ProcessBuilder.Redirect.INHERIT).start());
        }
        long sent = 0;
        double elapsed = 0;
        for (Process p : senders) {
            String line = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.US_ASCII).trim();
            if (p.waitFor() != 0 || !line.startsWith("sent ")) {
                throw new IllegalStateException("touchline-blast failed: " + line);
            }
            String[] words = line.split(" ");
            sent += Long.parseLong(words[1]);
            elapsed = Math.max(elapsed, Double.parseDouble(words[3]));
        }
        long received = decoded.awaitSettled() - startCount;
        return new IngestResult(sent, received, received / elapsed);
    }
}
