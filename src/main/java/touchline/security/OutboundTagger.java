package touchline.security;

/**
 * Tags everything the console sends to a small robot: appends the trailer with the next
 * counter. One per console; any thread.
 */
public final class OutboundTagger {

    private final MessageTag tag;
    private final CounterSource counters;

    public OutboundTagger(TeamKey key, CounterSource counters) {
        this.tag = new MessageTag(key);
        this.counters = counters;
    }

    public synchronized byte[] tag(int robotId, byte[] datagram) {
        return tag.append(MessageTag.TO_ROBOT, robotId, counters.next(), datagram);
    }

    public TeamKey key() {
        return tag.key();
    }
}
