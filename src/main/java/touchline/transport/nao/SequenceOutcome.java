package touchline.transport.nao;

import java.util.List;

/**
 * How a sequence of calls ended: the outcomes of the calls that were made, in order. A
 * sequence stops at the first call that did not succeed, so when {@link #ok()} is false the
 * last outcome is the failure and the calls after it were never sent.
 */
public record SequenceOutcome(List<NaoCall> calls, List<CallOutcome> outcomes) {

    public SequenceOutcome {
        calls = List.copyOf(calls);
        outcomes = List.copyOf(outcomes);
    }

    public boolean ok() {
        return outcomes.size() == calls.size() && outcomes.stream().allMatch(CallOutcome::ok);
    }

    /** Index of the failed call, or -1 when all succeeded. */
    public int failedIndex() {
        return ok() ? -1 : outcomes.size() - 1;
    }

    public String describe() {
        if (ok()) {
            return "done (" + calls.size() + " calls)";
        }
        int i = failedIndex();
        if (i < 0) {
            return "not run";
        }
        return calls.get(i).qualifiedName() + " (step " + (i + 1) + " of " + calls.size() + ") "
                + outcomes.get(i).describe();
    }
}
