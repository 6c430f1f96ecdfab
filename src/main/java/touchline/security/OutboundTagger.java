package touchline.security;

/**
 * Tags everything the console sends to a small robot: appends the trailer with the next
 * counter, bound to the boot the console believes the robot runs ({@link RobotBoots}; 0 before
 * the console has verified anything from it, which the robot refuses). One per console; any thread.
 */
public final class OutboundTagger {

    private final MessageTag tag;
    private final CounterSource counters;
    private final RobotBoots boots;

    public OutboundTagger(TeamKey key, CounterSource counters, RobotBoots boots) {
        this.tag = new MessageTag(key);
        this.counters = counters;
        this.boots = boots;
    }

    public synchronized byte[] tag(int robotId, byte[] datagram) {
        return tag.append(MessageTag.toRobot(boots.believed(robotId).orElse(0)), robotId, counters.next(), datagram);
    }

    public TeamKey key() {
        return tag.key();
    }
}
