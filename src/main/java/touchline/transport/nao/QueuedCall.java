package touchline.transport.nao;

import touchline.proto.Nao.HAWActorRPCRequest;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/**
 * One call the user made, from the moment it was accepted until its future completes: the
 * call, its request (without deadline: that is stamped at each send), its timeout, whether a
 * retry may resend it, and when it was made (on the link's monotonic clock: the console's, or a test's fake).
 */
record QueuedCall(NaoCall call, HAWActorRPCRequest.Builder request, long timeoutMillis, boolean idempotent,
                  CompletableFuture<CallOutcome> future, long submittedNanos) {

    /** When the whole call, retries included, is over. */
    long deadlineNanos() {
        return submittedNanos + TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
    }

    /** Completes the call with {@code outcome} unless it already ended. */
    void end(CallOutcome outcome) {
        future.complete(outcome);
    }
}
