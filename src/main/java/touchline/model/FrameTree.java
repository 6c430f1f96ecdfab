package touchline.model;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;

/**
 * One ROS 2 robot's TF tree in the plane, as its {@code /tf} and {@code /tf_static} messages
 * told it: each child frame has one parent (a newer transform of a child replaces the older, as
 * in tf2), and {@link #lookup} finds the transform between any two frames through their common
 * ancestor, in either direction. Immutable (a new transform gives a new tree), so a view reads
 * it while the stream thread adds to it. Bounded and hostile-proof: at most {@link #MAX_FRAMES}
 * child frames (more are counted as dropped), and a lookup walks at most {@link #MAX_FRAMES}
 * links, so a loop in a hostile tree (a → b → a) ends the walk rather than hanging it.
 */
public final class FrameTree {

    public static final int MAX_FRAMES = 64;
    public static final FrameTree EMPTY = new FrameTree(Map.of(), 0);

    private record Link(String parent, Transform2D transform) { }

    /** Where a lookup led: the transform target←source, or the frame the source's chain ended at. */
    public record Lookup(Transform2D transform, String endedAt) {

        public boolean found() {
            return transform != null;
        }

        /** Why there is no transform, in words: "no transform from odom". */
        public String reason() {
            return found() ? "" : "no transform from " + endedAt;
        }
    }

    private final Map<String, Link> parents;
    private final long dropped;

    private FrameTree(Map<String, Link> parents, long dropped) {
        this.parents = parents;
        this.dropped = dropped;
    }

    /**
     * This tree with {@code child} placed in {@code parent} by {@code transform} (parent←child). A
     * transform without both names, of a frame to itself or not finite is ignored; a new child beyond
     * {@link #MAX_FRAMES} is counted as dropped.
     */
    public FrameTree with(String parent, String child, Transform2D transform) {
        if (parent == null || child == null || parent.isEmpty() || child.isEmpty() || parent.equals(child)
                || !transform.isFinite()) {
            return this;
        }
        if (!parents.containsKey(child) && parents.size() >= MAX_FRAMES) {
            return new FrameTree(parents, dropped + 1);
        }
        Map<String, Link> next = new HashMap<>(parents);
        next.put(child, new Link(parent, transform));
        return new FrameTree(next, dropped);
    }

    /** Every frame named in the tree (parents and children), sorted. */
    public Set<String> frames() {
        Set<String> out = new TreeSet<>(parents.keySet());
        for (Link l : parents.values()) {
            out.add(l.parent());
        }
        return out;
    }

    /** Child frames refused beyond {@link #MAX_FRAMES}. */
    public long dropped() {
        return dropped;
    }

    /** The transform target←source: a point of {@code source} in {@code target}. */
    public Lookup lookup(String target, String source) {
        if (target.equals(source)) {
            return new Lookup(Transform2D.IDENTITY, source);
        }
        Map<String, Transform2D> fromSource = new HashMap<>();
        String top = up(source, fromSource);
        Map<String, Transform2D> fromTarget = new HashMap<>();
        up(target, fromTarget);
        // the nearest common ancestor a: target←source = (a←target)⁻¹ · (a←source)
        String at = target;
        Set<String> seen = new HashSet<>();
        while (at != null && seen.add(at)) {
            Transform2D toSource = fromSource.get(at);
            if (toSource != null) {
                return new Lookup(fromTarget.get(at).inverse().then(toSource), top);
            }
            Link l = parents.get(at);
            at = l == null || !fromTarget.containsKey(l.parent()) ? null : l.parent();
        }
        return new Lookup(null, top);
    }

    /**
     * Walks from {@code frame} up to its root, putting each ancestor's transform ancestor←frame into
     * {@code chain}; returns the last frame reached. Stops at a frame seen before (a loop) and after
     * {@link #MAX_FRAMES} links.
     */
    private String up(String frame, Map<String, Transform2D> chain) {
        Transform2D acc = Transform2D.IDENTITY;
        String at = frame;
        chain.put(at, acc);
        for (int depth = 0; depth < MAX_FRAMES; depth++) {
            Link l = parents.get(at);
            if (l == null || chain.containsKey(l.parent())) {
                break;
            }
            acc = l.transform().then(acc);
            at = l.parent();
            chain.put(at, acc);
        }
        return at;
    }
}
