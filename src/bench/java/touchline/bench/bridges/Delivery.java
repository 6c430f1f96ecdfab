package touchline.bench.bridges;

import java.util.Locale;

/**
 * One bridge's messages: what the simulated robot logged on channels the console had subscribed
 * to, and what the console counted in. Lost is the difference; more received than sent (a
 * subscription racing the robot's count by a message) is not a loss. Beside it what the console
 * counted but could not use: {@code unusable} (messages or channels the connection set aside, not
 * in received) and {@code undecodable} (received, but not fitting their channel's definition), so a
 * loss can be told from a message the console refused.
 */
public record Delivery(String bridge, long sent, long received, long unusable, long undecodable, double seconds) {

    // seconds: the robot's whole run; it counts from the console's subscription, a few seconds in,
    // so received/s reads a little under the robot's rate

    public long lost() {
        return Math.max(0, sent - received);
    }

    public double receivedPerSecond() {
        return seconds <= 0 ? 0 : received / seconds;
    }

    /** "| booster-1 | 6180 | 6180 | 0 | 0 | 0 | 103.0 |": a row under {@link #header()}. */
    public String row() {
        return String.format(Locale.ROOT, "| %s | %d | %d | %d | %d | %d | %.1f |", bridge, sent, received, lost(),
                unusable, undecodable, receivedPerSecond());
    }

    public static String header() {
        return "| bridge | sent to subscribers | received | lost | unusable | undecodable | received/s |\n"
                + "|---|---|---|---|---|---|---|";
    }
}
