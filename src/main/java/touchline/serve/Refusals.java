package touchline.serve;

import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;

/**
 * Connections the server turned away, by reason, for the status line ({@code refused 40
 * (upgrade slots full 33, upgrade deadline 7)}). Thread-safe.
 */
final class Refusals {

    /** Why a connection was turned away; {@link #words} is what the status line says. */
    enum Reason {
        TOKEN("no or wrong token"),
        ORIGIN("web page not allowed"),
        VIEWERS("too many viewers"),
        CONNECTIONS("too many connections"),
        UPGRADE_SLOTS("upgrade slots full"),
        UPGRADE_DEADLINE("upgrade deadline");

        final String words;

        Reason(String words) {
            this.words = words;
        }
    }

    private final Map<Reason, LongAdder> counts = new EnumMap<>(Reason.class);

    Refusals() {
        for (Reason r : Reason.values()) {
            counts.put(r, new LongAdder());
        }
    }

    void count(Reason r) {
        counts.get(r).increment();
    }

    long total() {
        return counts.values().stream().mapToLong(LongAdder::sum).sum();
    }

    /** The reasons counted so far, in the order of {@link Reason}, by their words. */
    Map<String, Long> byReason() {
        Map<String, Long> out = new LinkedHashMap<>();
        counts.forEach((r, n) -> {
            if (n.sum() > 0) {
                out.put(r.words, n.sum());
            }
        });
        return out;
    }
}
