package touchline.bench.record;

import touchline.record.PlaybackClock;
import touchline.record.Player;
import touchline.record.Recording;
import touchline.record.RecordingException;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicLong;

/** One headless replay of a whole file into a consumer that only counts: the replay benchmarks' baseline. */
record UnpacedReplay(long envelopes, double seconds) {

    static UnpacedReplay intoNothing(Path file) throws RecordingException {
        try (Recording r = Recording.open(file)) {
            AtomicLong n = new AtomicLong();
            Player p = new Player(r, e -> n.incrementAndGet(), new touchline.app.SystemClock());
            long t0 = System.nanoTime();
            p.runToEnd();
            return new UnpacedReplay(n.get(), (System.nanoTime() - t0) / 1e9);
        }
    }
}
