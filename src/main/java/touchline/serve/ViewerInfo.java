package touchline.serve;

import java.util.List;

/**
 * One connected viewer as the operator sees it (the window's Viewers view, {@code touchline
 * serve}'s statistics): where it connects from, the topics it subscribed to, and what it was
 * sent and what was dropped for it because it fell behind. A rate is the difference of two
 * snapshots.
 *
 * @param address  the viewer's address, e.g. {@code 10.0.0.9:51234}
 * @param topics   the topics it subscribed to, sorted
 * @param sent     messages sent to it so far
 * @param dropped  messages given up for it (a newer one of the same channel went out instead)
 */
public record ViewerInfo(String address, List<String> topics, long sent, long dropped) {
}
