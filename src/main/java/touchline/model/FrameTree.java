package touchline.model;

import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
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

    private record Parent(String frame, Transform2D transform) { }

    /** One TF link: {@code child} placed in {@code parent} (parent←child). */
    public record Link(String parent, String child, Transform2D transform) {

        boolean valid() {
            return parent != null && child != null && !parent.isEmpty() && !child.isEmpty() && !parent.equals(child)
                    && transform.isFinite();
        }
    }

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

    private final Map<String, Parent> parents;
    private final long dropped;

    private FrameTree(Map<String, Parent> parents, long dropped) {
        this.parents = parents;
        this.dropped = dropped;
    }

    /**
     * This tree with {@code child} placed in {@code parent} by {@code transform} (parent←child). A
     * transform without both names, of a frame to itself or not finite is ignored; a new child beyond
     * {@link #MAX_FRAMES} is counted as dropped.
     */
    public FrameTree with(String parent, String child, Transform2D transform) {
        return with(List.of(new Link(parent, child, transform)));
    }

    /** This tree with every link of one message placed (in one copy: a huge message costs no more per link). */
    public FrameTree with(List<Link> links) {
        if (links.isEmpty()) {
            return this;
        }
        Map<String, Parent> next = new HashMap<>(parents);
        long refused = dropped;
        for (Link l : links) {
            if (!l.valid()) {
                continue;
            }
            if (!next.containsKey(l.child()) && next.size() >= MAX_FRAMES) {
                refused++;
            } else {
                next.put(l.child(), new Parent(l.parent(), l.transform()));
            }
        }
        return new FrameTree(next, refused);
    }

    /** Every frame named in the tree (parents and children), sorted. */
    public Set<String> frames() {
        Set<String> out = new TreeSet<>(parents.keySet());
        for (Parent p : parents.values()) {
            out.add(p.frame());
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
            Parent p = parents.get(at);
            at = p == null || !fromTarget.containsKey(p.frame()) ? null : p.frame();
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
            Parent p = parents.get(at);
            if (p == null || chain.containsKey(p.frame())) {
                break;
            }
            acc = p.transform().then(acc);
            at = p.frame();
            chain.put(at, acc);
        }
        return at;
    }
}
