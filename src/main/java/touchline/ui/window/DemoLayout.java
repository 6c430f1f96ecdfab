package touchline.ui.window;

import touchline.ui.window.LayoutNode;
import touchline.ui.window.LayoutNode.Branch;
import touchline.ui.window.LayoutNode.Entry;
import touchline.ui.window.LayoutNode.Leaf;

import java.util.List;

/**
 * The arrangement a first start and {@code ./touchline demo} open: robots and options on the
 * left, camera overlay and plot top right, field and consoles below.
 */
final class DemoLayout {

    private DemoLayout() { }

    static List<LayoutNode> standard() {
        Leaf left = new Leaf(0, List.of(new Entry("robots", ""), new Entry("options", "")));
        Leaf overlay = new Leaf(0, List.of(new Entry("regions", "")));
        Leaf plot = new Leaf(0, List.of(new Entry("plot", "")));
        Leaf field = new Leaf(0, List.of(new Entry("field", "")));
        Leaf consoles = new Leaf(0, List.of(new Entry("debug-console", ""), new Entry("network", "")));
        Branch top = new Branch(false, List.of(0.5), List.of(overlay, plot));
        Branch bottom = new Branch(false, List.of(0.45), List.of(field, consoles));
        Branch right = new Branch(true, List.of(0.55), List.of(top, bottom));
        return List.of(new Branch(false, List.of(0.36), List.of(left, right)));
    }

    /** Options the demo switches on for every simulated robot, so its views fill at once. */
    static final List<String> DEMO_OPTIONS = List.of("havimo.region", "havimo.grid", "demo.plotter", "demo.text");

    /** What the demo's robots send in the game (their match digest), first first: the plot and the field move once a second. */
    static final List<String> MATCH_ITEMS = List.of("demo.plotter", "demo.field");
}
