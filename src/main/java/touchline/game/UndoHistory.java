package touchline.game;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;

/**
 * The last {@code depth} applied actions of a game with the state before each, most recent
 * first, for undo. Not thread-safe: the game that owns it serialises access.
 *
 * @param <S> the game's state type
 */
public final class UndoHistory<S> {

    /**
     * One undoable action.
     *
     * @param description what was done, e.g. {@code goal 5}
     * @param before      the state before it
     */
    public record Done<S>(String description, S before) {
    }

    private final int depth;
    private final Deque<Done<S>> done = new ArrayDeque<>();

    public UndoHistory(int depth) {
        this.depth = depth;
    }

    public void push(String description, S before) {
        done.push(new Done<>(description, before));
        while (done.size() > depth) {
            done.removeLast();
        }
    }

    /** The most recent action, removed from the history; null when there is none. */
    public Done<S> pop() {
        return done.poll();
    }

    /** Descriptions, most recent first. */
    public List<String> descriptions() {
        List<String> out = new ArrayList<>();
        done.forEach(d -> out.add(d.description()));
        return out;
    }
}
