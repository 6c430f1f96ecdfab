package touchline.ui.referee;

import touchline.app.game.GameRuntime;
import touchline.game.Outcome;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * The referee's own actions on their way to the game's owner and what became of them, as the box
 * shows it, without JavaFX: a press only enqueues and hands its pending outcome here
 * ({@link #expect}); each frame {@link #pull}s the outcomes that came, in the order the actions
 * went, and the line says the last one (what was done, or why it was refused). The JavaFX thread
 * never waits for the owner: an action still unanswered after {@link GameRuntime#ANSWER_MS} on
 * the game's clock shows as not answered until its outcome comes.
 */
final class RefereeOutcomes {

    /** An action enqueued, when (the game's clock), and what its outcome does besides being shown. */
    private record Pending(CompletableFuture<Outcome> outcome, long sinceMs, Consumer<Outcome> then) {
    }

    private final LongSupplier clock;
    private final Deque<Pending> pending = new ArrayDeque<>();
    private String message = "";
    private boolean refused;

    /** @param clock the game's clock in milliseconds (the owner's {@code now}) */
    RefereeOutcomes(LongSupplier clock) {
        this.clock = clock;
    }

    /** An action just enqueued: its outcome is shown once it came. */
    void expect(CompletableFuture<Outcome> outcome) {
        expect(outcome, o -> { });
    }

    /** As {@link #expect(CompletableFuture)}, and {@code then} runs with the outcome (in {@link #pull}). */
    void expect(CompletableFuture<Outcome> outcome, Consumer<Outcome> then) {
        pending.addLast(new Pending(outcome, clock.getAsLong(), then));
    }

    /** At a frame: takes the outcomes that came (never waits for one that did not). */
    void pull() {
        while (!pending.isEmpty() && pending.peekFirst().outcome().isDone()) {
            Pending p = pending.pollFirst();
            Outcome o = GameRuntime.outcome(p.outcome()); // done: no wait, only its words
            say(o.message(), !o.applied());
            p.then().accept(o);
        }
        Pending oldest = pending.peekFirst();
        if (oldest != null && clock.getAsLong() - oldest.sinceMs() >= GameRuntime.ANSWER_MS) {
            Outcome late = GameRuntime.unanswered();
            say(late.message(), !late.applied());
        }
    }

    /** A line of the box's own (a penalty call chosen, or why it cannot be). */
    void say(String line, boolean refusal) {
        message = line;
        refused = refusal;
    }

    /** The last outcome: what was done, or why it was refused. */
    String message() {
        return message;
    }

    boolean refused() {
        return refused;
    }

    /** Whether an action enqueued has not been answered yet (as of the last {@link #pull}). */
    boolean waiting() {
        return !pending.isEmpty();
    }
}
