package touchline.transport.nao;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.Function;

/**
 * Calls run one after the other, each after the previous one succeeded, stopping at the first
 * failure (whose outcome is the last in the result). Never completes exceptionally.
 */
final class CallSequence {

    private final Function<NaoCall, CompletableFuture<CallOutcome>> caller;

    /** @param caller makes one call (the link's {@link NaoLink#call(NaoCall)}) */
    CallSequence(Function<NaoCall, CompletableFuture<CallOutcome>> caller) {
        this.caller = caller;
    }

    CompletableFuture<SequenceOutcome> run(List<NaoCall> calls) {
        CompletableFuture<SequenceOutcome> result = new CompletableFuture<>();
        step(calls, 0, new ArrayList<>(), result);
        return result;
    }

    private void step(List<NaoCall> calls, int index, List<CallOutcome> outcomes,
                      CompletableFuture<SequenceOutcome> result) {
        if (index == calls.size()) {
            result.complete(new SequenceOutcome(calls, outcomes));
            return;
        }
        caller.apply(calls.get(index)).thenAccept(outcome -> {
            outcomes.add(outcome);
            if (outcome.ok()) {
                step(calls, index + 1, outcomes, result);
            } else {
                result.complete(new SequenceOutcome(calls, outcomes));
            }
        });
    }
}
