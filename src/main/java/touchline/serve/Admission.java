package touchline.serve;

import io.netty.channel.Channel;
import io.netty.util.concurrent.ScheduledFuture;

import java.util.concurrent.ConcurrentLinkedDeque;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Holds every accepted connection to its {@link ConnectionLimits}: the cap on all connections,
 * the cap on those still before their upgrade (the oldest gives way), and the upgrade deadline
 * counted from accept. Thread-safe: connections are accepted on several event loops.
 */
final class Admission {

    private final ConnectionLimits limits;
    private final Refusals refusals;
    private final AtomicInteger open = new AtomicInteger();
    private final ConcurrentLinkedDeque<Channel> upgrading = new ConcurrentLinkedDeque<>(); // oldest first
    private final AtomicInteger upgradingCount = new AtomicInteger();

    Admission(ConnectionLimits limits, Refusals refusals) {
        this.limits = limits;
        this.refusals = refusals;
    }

    /** On {@code ch}'s event loop, as it is registered: false (and closed, counted) when over the cap. */
    boolean admit(Channel ch) {
        if (open.incrementAndGet() > limits.maxConnections()) {
            open.decrementAndGet();
            refusals.count(Refusals.Reason.CONNECTIONS);
            ch.close();
            return false;
        }
        upgrading.addLast(ch);
        upgradingCount.incrementAndGet();
        ScheduledFuture<?> deadline = ch.eventLoop().schedule(() -> cut(ch, Refusals.Reason.UPGRADE_DEADLINE),
                limits.upgradeMillis(), TimeUnit.MILLISECONDS);
        ch.closeFuture().addListener(f -> {
            deadline.cancel(false);
            open.decrementAndGet();
            done(ch);
        });
        while (upgradingCount.get() > limits.maxUpgrading()) {
            Channel oldest = upgrading.peekFirst();
            if (oldest == null) {
                break;
            }
            cut(oldest, Refusals.Reason.UPGRADE_SLOTS);
        }
        return true;
    }

    /** {@code ch} finished its upgrade: it is a viewer (or refused as one) from now on. */
    void upgraded(Channel ch) {
        done(ch);
    }

    /** Connections open now that have not finished their upgrade. */
    int upgrading() {
        return upgradingCount.get();
    }

    /** Connections open now. */
    int open() {
        return open.get();
    }

    private void cut(Channel ch, Refusals.Reason why) {
        if (done(ch)) {
            refusals.count(why);
            ch.close();
        }
    }

    /** Takes {@code ch} off the waiting list; true when this call did. */
    private boolean done(Channel ch) {
        if (upgrading.remove(ch)) {
            upgradingCount.decrementAndGet();
            return true;
        }
        return false;
    }
}
