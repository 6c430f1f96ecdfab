package touchline.record;

import touchline.bench.record.SyntheticTeam;
import touchline.transport.Envelope;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/** Synthetic team traffic written to an MCAP file, shared by the recording tests. */
final class RecordingFixture {

    static final long START = 1_760_000_000_000_000L;

    private RecordingFixture() {
    }

    static List<Envelope> team(int robots, long seconds) {
        List<Envelope> out = new ArrayList<>();
        new SyntheticTeam(robots, START, 42).generate(seconds, out::add);
        return out;
    }

    static void write(Path file, List<Envelope> envelopes, EnvelopeWriter.Options options) throws IOException {
        try (EnvelopeWriter w = new EnvelopeWriter(file, options)) {
            for (Envelope e : envelopes) {
                w.write(e);
            }
        }
    }

    static List<Envelope> readAll(Recording r) {
        List<Envelope> out = new ArrayList<>();
        Recording.Cursor c = r.cursor(Long.MIN_VALUE);
        for (Envelope e = c.next(); e != null; e = c.next()) {
            out.add(e);
        }
        return out;
    }
}
