package touchline.model;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.*;

/** The TF tree in the plane: chains, either direction, missing links, and hostile trees that must not hang. */
class FrameTreeTest {

    private static final double EPS = 1e-9;

    private static void assertPoint(double x, double y, FrameTree.Lookup l, double px, double py) {
        assertTrue(l.found(), l.reason());
        double[] p = l.transform().apply(px, py);
        assertEquals(x, p[0], EPS, "x");
        assertEquals(y, p[1], EPS, "y");
    }

    /** map→odom: odom's origin at (1, 2) of map, turned a quarter; odom→base_link: the robot 3 m ahead in odom. */
    private static FrameTree mapOdomBase() {
        return FrameTree.EMPTY.with("map", "odom", new Transform2D(1, 2, Math.PI / 2))
                .with("odom", "base_link", new Transform2D(3, 0, 0));
    }

    @Test
    void aChainOfTransformsPlacesTheRobotInTheRootFrame() {
        FrameTree.Lookup l = mapOdomBase().lookup("map", "base_link");
        // 3 m ahead in odom is 3 m along map's y once turned a quarter, from (1, 2)
        assertPoint(1, 5, l, 0, 0);
        assertEquals(Math.PI / 2, l.transform().yaw(), EPS);
        assertPoint(0, 6, l, 1, 1);
    }

    @Test
    void theInverseDirectionUndoesIt() {
        FrameTree t = mapOdomBase();
        assertPoint(0, 0, t.lookup("base_link", "map"), 1, 5);
        assertPoint(3, 0, t.lookup("odom", "map"), 1, 5);
        FrameTree.Lookup there = t.lookup("map", "base_link");
        FrameTree.Lookup back = t.lookup("base_link", "map");
        Transform2D round = there.transform().then(back.transform());
        assertEquals(0, round.x(), EPS);
        assertEquals(0, round.y(), EPS);
        assertEquals(0, round.yaw(), EPS);
    }

    @Test
    void siblingsMeetAtTheirCommonParent() {
        FrameTree t = mapOdomBase().with("base_link", "camera", new Transform2D(0.1, 0, 0))
                .with("base_link", "left_foot", new Transform2D(0, 0.1, 0));
        assertPoint(0.1, -0.1, t.lookup("left_foot", "camera"), 0, 0);
        assertPoint(1, 5.1, t.lookup("map", "camera"), 0, 0);
    }

    @Test
    void aFrameIsItselfEvenWhenTheTreeDoesNotKnowIt() {
        assertPoint(4, 5, FrameTree.EMPTY.lookup("field", "field"), 4, 5);
    }

    @Test
    void aMissingLinkSaysWhereTheChainEnded() {
        FrameTree t = FrameTree.EMPTY.with("odom", "base_link", new Transform2D(3, 0, 0));
        FrameTree.Lookup l = t.lookup("map", "base_link");
        assertFalse(l.found());
        assertEquals("no transform from odom", l.reason());
        assertEquals("no transform from field", t.lookup("map", "field").reason());
    }

    @Test
    void aNewerTransformOfAChildReplacesTheOlder() {
        FrameTree t = mapOdomBase().with("odom", "base_link", new Transform2D(0, 0, 0));
        assertPoint(1, 2, t.lookup("map", "base_link"), 0, 0);
        // moved to another parent: the old chain is gone
        FrameTree moved = t.with("world", "base_link", new Transform2D(7, 0, 0));
        assertEquals("no transform from world", moved.lookup("map", "base_link").reason());
    }

    @Test
    void aLoopInAHostileTreeEndsTheWalk() {
        FrameTree loop = FrameTree.EMPTY.with("a", "b", new Transform2D(1, 0, 0)).with("b", "a", new Transform2D(1, 0, 0))
                .with("b", "c", new Transform2D(0, 1, 0));
        assertFalse(loop.lookup("map", "c").found());
        assertTrue(loop.lookup("b", "c").found());
        assertFalse(loop.lookup("c", "map").found());
    }

    @Test
    void aLongChainIsWalkedToItsBoundAndMoreFramesAreDropped() {
        FrameTree t = FrameTree.EMPTY;
        for (int i = 0; i < FrameTree.MAX_FRAMES + 10; i++) {
            t = t.with("f" + (i + 1), "f" + i, new Transform2D(1, 0, 0));
        }
        assertEquals(10, t.dropped());
        assertEquals(FrameTree.MAX_FRAMES + 1, t.frames().size());
        assertPoint(5, 0, t.lookup("f5", "f0"), 0, 0);
        assertTrue(t.lookup("f" + FrameTree.MAX_FRAMES, "f0").found());
    }

    @Test
    void nonsenseIsIgnored() {
        FrameTree t = FrameTree.EMPTY.with("", "a", Transform2D.IDENTITY).with("a", "a", Transform2D.IDENTITY)
                .with("a", "b", new Transform2D(Double.NaN, 0, 0)).with(null, "b", Transform2D.IDENTITY);
        assertTrue(t.frames().isEmpty());
    }

    @Test
    void aQuaternionGivesItsYaw() {
        double half = Math.PI / 8;
        assertEquals(Math.PI / 4, Transform2D.of(0, 0, 0, 0, Math.sin(half), Math.cos(half)).yaw(), EPS);
        assertEquals(0, Transform2D.of(0, 0, 0, 0, 0, 0).yaw(), EPS);
    }

    @Test
    void aHugeMessageIsPlacedInOneGoAndStaysBounded() {
        java.util.List<FrameTree.Link> links = new java.util.ArrayList<>();
        for (int i = 0; i < 100_000; i++) {
            links.add(new FrameTree.Link("map", "f" + i, new Transform2D(i, 0, 0)));
        }
        FrameTree t = FrameTree.EMPTY.with(links);
        assertEquals(FrameTree.MAX_FRAMES + 1, t.frames().size());
        assertEquals(100_000 - FrameTree.MAX_FRAMES, t.dropped());
        assertPoint(3, 0, t.lookup("map", "f3"), 0, 0);
    }
}
