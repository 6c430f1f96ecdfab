package touchline.ui.window;

import javafx.geometry.Orientation;
import javafx.scene.layout.BorderPane;
import software.coley.bentofx.Bento;
import software.coley.bentofx.dockable.Dockable;
import software.coley.bentofx.layout.DockContainer;
import software.coley.bentofx.layout.container.DockContainerBranch;
import software.coley.bentofx.layout.container.DockContainerLeaf;
import software.coley.bentofx.layout.container.DockContainerRootBranch;
import touchline.ui.window.LayoutNode;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewFrame;
import touchline.ui.frame.ViewSource;

/**
 * The docking area (BentoFX): views live in tabs the user drags between split panes or out
 * into their own windows. The shell knows which {@link View} each tab holds, so the frame
 * pulse can refresh the open ones and a layout can be captured and rebuilt.
 */
public final class Shell {

    /** An open view, the registry entry it came from, and the frame that keeps its faults in its tab. */
    public record OpenView(ViewSpec spec, ViewFrame frame, Dockable dockable) {

        /** The view now in the frame (a reopened view is a new instance). */
        public View view() {
            return frame.view();
        }
    }

    private final Bento bento = new Bento();
    private final ViewRegistry registry;
    private final Function<ViewSpec, Function<ViewSource, View>> maker;
    private final BorderPane host = new BorderPane();
    private final Map<Dockable, OpenView> open = new LinkedHashMap<>();
    private DockContainerRootBranch root;
    private Runnable changed = () -> { };

    public Shell(ViewRegistry registry, Function<ViewSpec, Function<ViewSource, View>> maker) {
        this.registry = registry;
        this.maker = maker;
        bento.events().addDockableCloseListener((path, d) -> forget(d));
        bento.controlsBuilding().setCanvasFactory(leaf -> new DropHint());
        root = bento.dockBuilding().root("main");
        host.setCenter(root);
    }

    /** Called whenever a view opens, closes or is brought to front (the idle frame pulse wakes up). */
    public void onChange(Runnable r) {
        changed = r;
    }

    public BorderPane node() {
        return host;
    }

    public Bento bento() {
        return bento;
    }

    public Collection<OpenView> openViews() {
        return List.copyOf(open.values());
    }

    /** The open views as the frame pulse pulls them. */
    public List<touchline.ui.frame.PulledView> pulled() {
        return open.values().stream().map(v -> new touchline.ui.frame.PulledView(v.spec().id(), v.frame())).toList();
    }

    /** The open view {@code node} lies in (the focused node, for F1), if any. */
    public java.util.Optional<OpenView> containing(javafx.scene.Node node) {
        for (javafx.scene.Node n = node; n != null; n = n.getParent()) {
            for (OpenView v : open.values()) {
                if (v.frame() == n) {
                    return java.util.Optional.of(v);
                }
            }
        }
        return java.util.Optional.empty();
    }

    private void forget(Dockable d) {
        OpenView v = open.remove(d);
        changed.run();
        if (v != null) {
            v.view().close();
        }
    }

    /** Opens a view (or selects it when the same view with the same source is already open). */
    public OpenView open(ViewSpec spec, ViewSource source) {
        changed.run();
        for (OpenView v : open.values()) {
            ViewSource s = v.view().source();
            if (v.spec().equals(spec) && (s == null || !source.isSet() || source.equals(s))) {
                if (v.dockable().getContainer() != null) {
                    v.dockable().getContainer().selectDockable(v.dockable());
                }
                return v;
            }
        }
        OpenView v = create(spec, source);
        DockContainerLeaf target = largestLeaf();
        if (target == null) {
            target = bento.dockBuilding().leaf();
            root.addContainer(target);
        } else if (spec.needWidth() > target.getWidth() + 0.5 && leaves(root).size() > 1) {
            target = fullWidthRow(); // the referee's both teams, the NAO's Connect: no dragging of dividers
        }
        target.addDockable(v.dockable());
        target.selectDockable(v.dockable());
        return v;
    }

    /**
     * Opens a view as {@link #open} does and moves the keyboard into it: its first control that
     * takes the keyboard gets it, now or as soon as the view is in the window (Ctrl+K, the View
     * menu). The options tree, which opens views too, keeps the keyboard.
     */
    public OpenView openAndFocus(ViewSpec spec, ViewSource source) {
        OpenView v = open(spec, source);
        javafx.scene.Node node = v.view().node();
        if (node.getScene() != null) {
            focusFirst(node); // a view with nothing that takes the keyboard leaves it where it was
        } else {
            node.sceneProperty().addListener(new javafx.beans.value.ChangeListener<javafx.scene.Scene>() {
                @Override
                public void changed(javafx.beans.value.ObservableValue<? extends javafx.scene.Scene> o,
                                    javafx.scene.Scene was, javafx.scene.Scene now) {
                    if (now != null) {
                        o.removeListener(this);
                        javafx.application.Platform.runLater(() -> focusFirst(node));
                    }
                }
            });
        }
        return v;
    }

    /** The first node at or under {@code node}, in the order Tab walks, that takes the keyboard gets it. */
    private static boolean focusFirst(javafx.scene.Node node) {
        if (!node.isVisible() || node.isDisabled()) {
            return false;
        }
        if (node.isFocusTraversable()) {
            node.requestFocus();
            return true;
        }
        if (node instanceof javafx.scene.Parent p) {
            for (javafx.scene.Node child : p.getChildrenUnmodifiable()) {
                if (focusFirst(child)) {
                    return true;
                }
            }
        }
        return false;
    }

    private OpenView create(ViewSpec spec, ViewSource source) {
        ViewFrame frame = new ViewFrame(spec.title(), () -> maker.apply(spec).apply(source));
        Dockable d = bento.dockBuilding().dockable();
        d.setTitle(spec.title() + (source.isSet() ? " · " + source.robotId() + " " + source.option() : ""));
        d.setNode(frame);
        d.setTooltip(new javafx.scene.control.Tooltip(spec.help()));
        OpenView v = new OpenView(spec, frame, d);
        open.put(d, v);
        // a view joins the screen a layout pass after it opens: that wakes the (maybe idle) frame
        // pulse too, so its first pull never waits for a change of data
        frame.sceneProperty().addListener((o, was, now) -> {
            if (now != null) {
                changed.run();
            }
        });
        return v;
    }

    /** The window's share of its height a view gets in a row of the whole width ({@link #fullWidthRow}). */
    static final double WIDE_ROW_SHARE = 0.6;

    /**
     * A new pane across the whole window at the bottom, the layout as it was above it: for a view
     * that needs more width than any pane has.
     */
    private DockContainerLeaf fullWidthRow() {
        DockContainerBranch above = bento.dockBuilding().branch();
        above.setOrientation(root.getOrientation());
        double[] positions = root.getDividerPositions();
        for (DockContainer c : List.copyOf(root.getChildContainers())) {
            root.removeContainer(c);
            above.addContainer(c);
        }
        DockContainerLeaf row = bento.dockBuilding().leaf();
        root.setOrientation(Orientation.VERTICAL);
        root.addContainer(above);
        root.addContainer(row);
        Runnable dividers = () -> {
            above.setDividerPositions(positions);
            root.setDividerPositions(1 - WIDE_ROW_SHARE);
        };
        dividers.run();
        javafx.application.Platform.runLater(dividers); // as restore does: once more after the layout pass
        return row;
    }

    private DockContainerLeaf largestLeaf() {
        DockContainerLeaf best = null;
        double bestArea = -1;
        for (DockContainerLeaf l : leaves(root)) {
            double area = l.getWidth() * l.getHeight();
            if (area > bestArea) {
                best = l;
                bestArea = area;
            }
        }
        return best;
    }

    private static List<DockContainerLeaf> leaves(DockContainer c) {
        List<DockContainerLeaf> out = new ArrayList<>();
        if (c instanceof DockContainerLeaf l) {
            out.add(l);
        } else if (c instanceof DockContainerBranch b) {
            for (DockContainer child : b.getChildContainers()) {
                out.addAll(leaves(child));
            }
        }
        return out;
    }

    /** The arrangement of every window (main first) as plain layout data. */
    public List<LayoutNode> capture() {
        List<LayoutNode> windows = new ArrayList<>();
        windows.add(capture(root));
        for (DockContainerRootBranch r : bento.getRootContainers()) {
            if (r != root) {
                windows.add(capture(r));
            }
        }
        return windows;
    }

    private LayoutNode capture(DockContainer c) {
        if (c instanceof DockContainerLeaf l) {
            List<LayoutNode.Entry> views = new ArrayList<>();
            int selected = 0;
            for (Dockable d : l.getDockables()) {
                OpenView v = open.get(d);
                if (v != null) {
                    if (d == l.getSelectedDockable()) {
                        selected = views.size();
                    }
                    ViewSource s = v.view().source();
                    String state = v.view().layoutState();
                    views.add(new LayoutNode.Entry(v.spec().id(),
                            state != null ? state : s == null || !s.isSet() ? "" : s.encode()));
                }
            }
            return new LayoutNode.Leaf(selected, views);
        }
        DockContainerBranch b = (DockContainerBranch) c;
        List<Double> dividers = new ArrayList<>();
        for (double d : b.getDividerPositions()) {
            dividers.add(d);
        }
        List<LayoutNode> children = new ArrayList<>();
        for (DockContainer child : b.getChildContainers()) {
            children.add(capture(child));
        }
        return new LayoutNode.Branch(b.getOrientation() == Orientation.VERTICAL, dividers, children);
    }

    /**
     * Replaces the arrangement: closes every view and builds the saved one. Views the registry
     * no longer has are skipped; views whose robot is absent open and wait for it. Detached
     * windows of the layout are docked into the main window.
     */
    public void restore(List<LayoutNode> windows) {
        changed.run();
        for (OpenView v : List.copyOf(open.values())) {
            v.view().close();
        }
        open.clear();
        DockContainerRootBranch fresh = bento.dockBuilding().root("main");
        List<Runnable> dividers = new ArrayList<>();
        for (LayoutNode w : windows) {
            DockContainer c = build(w, dividers);
            if (c == null) {
                continue;
            }
            if (c instanceof DockContainerBranch b && fresh.getChildContainers().isEmpty() && windows.get(0) == w) {
                fresh.setOrientation(b.getOrientation());
                for (DockContainer child : List.copyOf(b.getChildContainers())) {
                    b.removeContainer(child);
                    fresh.addContainer(child);
                }
                double[] pos = ((LayoutNode.Branch) w).dividers().stream().mapToDouble(Double::doubleValue).toArray();
                dividers.add(() -> fresh.setDividerPositions(pos));
            } else {
                fresh.addContainer(c);
            }
        }
        root = fresh;
        host.setCenter(root);
        dividers.forEach(Runnable::run);
        javafx.application.Platform.runLater(() -> dividers.forEach(Runnable::run));
    }

    private DockContainer build(LayoutNode node, List<Runnable> dividers) {
        if (node instanceof LayoutNode.Leaf l) {
            List<Dockable> made = new ArrayList<>();
            for (LayoutNode.Entry e : l.views()) {
                registry.byId(e.viewId()).ifPresent(spec -> {
                    OpenView v = create(spec, ViewSource.decode(e.source()));
                    v.view().restoreLayoutState(e.source());
                    made.add(v.dockable());
                });
            }
            if (made.isEmpty()) {
                return null;
            }
            DockContainerLeaf leaf = bento.dockBuilding().leaf();
            made.forEach(leaf::addDockable);
            leaf.selectDockable(made.get(Math.max(0, Math.min(made.size() - 1, l.selected()))));
            return leaf;
        }
        LayoutNode.Branch b = (LayoutNode.Branch) node;
        List<DockContainer> children = new ArrayList<>();
        for (LayoutNode c : b.children()) {
            DockContainer built = build(c, dividers);
            if (built != null) {
                children.add(built);
            }
        }
        if (children.isEmpty()) {
            return null;
        }
        if (children.size() == 1) {
            return children.get(0);
        }
        DockContainerBranch branch = bento.dockBuilding().branch();
        branch.setOrientation(b.vertical() ? Orientation.VERTICAL : Orientation.HORIZONTAL);
        children.forEach(branch::addContainer);
        if (b.dividers().size() == children.size() - 1) {
            double[] pos = b.dividers().stream().mapToDouble(Double::doubleValue).toArray();
            dividers.add(() -> branch.setDividerPositions(pos));
        }
        return branch;
    }
}
