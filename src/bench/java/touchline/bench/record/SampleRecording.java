package touchline.bench.record;

import touchline.record.EnvelopeWriter;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Instant;

/**
 * Writes {@code samples/demo-team.mcap}: three minutes of a simulated three-robot team from
 * {@link SyntheticTeam} (deterministic, so the file is reproducible). Usage:
 * {@code java ... touchline.bench.record.SampleRecording [FILE] [SECONDS]}.
 */
public final class SampleRecording {

    /** 2026-06-01 10:00 UTC, a plausible match time; fixed so the sample is byte-for-byte reproducible. */
    static final long START_MICROS = Instant.parse("2026-06-01T10:00:00Z").toEpochMilli() * 1000L;

    private SampleRecording() {
    }

    public static void main(String[] args) throws IOException {
        Path file = Path.of(args.length > 0 ? args[0] : "samples/demo-team.mcap");
        long seconds = args.length > 1 ? Long.parseLong(args[1]) : 180;
        long[] count = {0};
        try (EnvelopeWriter w = new EnvelopeWriter(file, EnvelopeWriter.Options.defaults())) {
            new SyntheticTeam(3, START_MICROS, 2026).generate(seconds, (Envelope e) -> {
                try {
                    w.write(e);
                    count[0]++;
                } catch (IOException x) {
                    throw new UncheckedIOException(x);
                }
            });
        }
        System.out.println("wrote " + count[0] + " envelopes, " + seconds + " s, to " + file);
    }
}
