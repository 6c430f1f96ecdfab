package touchline.transport.nao;

import java.util.concurrent.atomic.AtomicLong;

/**
 * The counts a NAO link keeps itself (requests sent, calls answered, calls lost, retries);
 * {@link #stats} joins them with the call table's, the pacing's and the reply reader's into
 * {@link NaoLink.LinkStats}. Counted on the link's lock, read from any thread.
 */
final class LinkCounters {

    private final AtomicLong sent = new AtomicLong();
    private final AtomicLong answered = new AtomicLong();
    private final AtomicLong lost = new AtomicLong();
    private final AtomicLong retried = new AtomicLong();

    void sent() {
        sent.incrementAndGet();
    }

    void answered() {
        answered.incrementAndGet();
    }

    void lost(long calls) {
        lost.addAndGet(calls);
    }

    void retried() {
        retried.incrementAndGet();
    }

    NaoLink.LinkStats stats(PendingCalls pending, CallPacing pacing, ReplyReader replies) {
        return new NaoLink.LinkStats(sent.get(), answered.get(), pending.timeouts() + pacing.timeouts(),
                pending.strays(), replies.malformed(), lost.get(), retried.get());
    }
}
