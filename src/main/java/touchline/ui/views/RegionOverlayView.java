package touchline.ui.views;

import javafx.scene.canvas.GraphicsContext;
import javafx.scene.paint.Color;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.ResizableCanvas;
import touchline.ui.SourcedView;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.util.Set;
import java.util.TreeSet;

/**
 * The HaViMo2 camera's view: the whole frame as a blue rectangle, each region-growing blob as
 * a red rectangle filled in its colour class, the gridding result as translucent cells, and a
 * legend. Regions reaching outside the frame are clipped to it and drawn dashed; the status
 * line counts them.
 */
public final class RegionOverlayView extends SourcedView {

    static final int DEFAULT_WIDTH = 160;
    static final int DEFAULT_HEIGHT = 120;
    /** Behind the frame and around it. */
    static final Color BACKGROUND = Color.gray(0.12);
    /** How much of its class's colour a grid cell shows over the background. */
    static final double GRID_OPACITY = 0.3;
    /** Each colour class's grid cell, mixed once ({@link #gridCell}). */
    private static final Color[] GRID_CELLS = new Color[256];

    static {
        for (int c = 0; c < GRID_CELLS.length; c++) {
            GRID_CELLS[c] = BACKGROUND.interpolate(ColorClasses.color(c), GRID_OPACITY);
        }
    }
    private final ResizableCanvas canvas = new ResizableCanvas(() -> dirty = true);

    public RegionOverlayView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.REGION_GROWING_VALUE, Fumanoid.DebugKind.GRID_VALUE), source);
        canvas.setId("region-canvas");
        root.setCenter(canvas);
    }

    @Override
    protected void empty() {
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        g.clearRect(0, 0, canvas.getWidth(), canvas.getHeight());
    }

    @Override
    protected String draw(Latest latest) {
        Fumanoid.RegionGrowing regions = latest.data() instanceof Fumanoid.RegionGrowing r ? r : null;
        Fumanoid.Grid grid = latest.data() instanceof Fumanoid.Grid gr ? gr : null;
        // the other half of the picture: the same robot's newest grid (or regions)
        if (grid == null) {
            grid = newest(latest.robotId(), "grid", Fumanoid.Grid.class);
        }
        if (regions == null) {
            regions = newest(latest.robotId(), "regionGrowing", Fumanoid.RegionGrowing.class);
        }
        int fw = DEFAULT_WIDTH;
        int fh = DEFAULT_HEIGHT;
        if (regions != null && regions.getFrameWidth() > 0 && regions.getFrameHeight() > 0) {
            fw = regions.getFrameWidth();
            fh = regions.getFrameHeight();
        } else if (grid != null && grid.getFrameWidth() > 0 && grid.getFrameHeight() > 0) {
            fw = grid.getFrameWidth();
            fh = grid.getFrameHeight();
        }
        GraphicsContext g = canvas.canvas().getGraphicsContext2D();
        double w = canvas.getWidth();
        double h = canvas.getHeight();
        g.setFill(BACKGROUND);
        g.fillRect(0, 0, w, h);
        double legend = 24;
        double margin = 24;
        double scale = Math.max(0.01, Math.min((w - 2 * margin) / fw, (h - 2 * margin - legend) / fh));
        double ox = (w - fw * scale) / 2;
        double oy = margin;
        Set<Integer> classes = new TreeSet<>();
        String gridNote = "";
        if (grid != null) {
            gridNote = drawGrid(g, grid, fw, fh, ox, oy, scale, classes);
        }
        int shown = 0;
        int clipped = 0;
        int invalid = 0;
        if (regions != null) {
            for (Fumanoid.Region r : regions.getRegionsList()) {
                int x1 = Math.min(r.getX1(), r.getX2());
                int x2 = Math.max(r.getX1(), r.getX2());
                int y1 = Math.min(r.getY1(), r.getY2());
                int y2 = Math.max(r.getY1(), r.getY2());
                int cx1 = Math.max(0, x1);
                int cy1 = Math.max(0, y1);
                int cx2 = Math.min(fw, x2);
                int cy2 = Math.min(fh, y2);
                if (cx1 >= cx2 || cy1 >= cy2) {
                    invalid++; // wholly outside the frame or empty: nothing to draw
                    continue;
                }
                boolean wasClipped = cx1 != x1 || cy1 != y1 || cx2 != x2 || cy2 != y2;
                classes.add(r.getColorClass());
                Color c = ColorClasses.color(r.getColorClass());
                g.setFill(c.deriveColor(0, 1, 1, 0.35));
                g.fillRect(ox + cx1 * scale, oy + cy1 * scale, (cx2 - cx1) * scale, (cy2 - cy1) * scale);
                if (wasClipped) {
                    g.setStroke(Color.RED);
                    g.setLineWidth(2);
                    g.setLineDashes(6, 4);
                    g.strokeRect(ox + cx1 * scale, oy + cy1 * scale, (cx2 - cx1) * scale, (cy2 - cy1) * scale);
                    g.setLineDashes(null);
                } else {
                    g.setFill(Color.RED);
                    CrispLines.outline(g, ox + cx1 * scale, oy + cy1 * scale, (cx2 - cx1) * scale, (cy2 - cy1) * scale, 2);
                }
                if (wasClipped) {
                    clipped++;
                }
                shown++;
            }
        }
        g.setFill(Color.DODGERBLUE);
        CrispLines.outline(g, ox - 1, oy - 1, fw * scale + 2, fh * scale + 2, 2);
        drawLegend(g, classes, h - legend + 4, w);
        StringBuilder s = new StringBuilder("frame " + fw + "×" + fh + " · " + shown + " regions");
        if (clipped > 0) {
            s.append(" · ").append(clipped).append(" clipped to the frame (dashed)");
        }
        if (invalid > 0) {
            s.append(" · ").append(invalid).append(" outside the frame or empty, not drawn");
        }
        if (grid != null) {
            s.append(" · grid ").append(grid.getColumns()).append("×").append(grid.getRows()).append(gridNote);
        }
        return s.toString();
    }

    /**
     * A grid cell of colour class {@code c}: its colour at {@link #GRID_OPACITY} over the
     * background, mixed here once and opaque. Cells lie on the plain background, so they look
     * the same as translucent fills, but JavaFX's software renderer stores an opaque pixel where
     * it blends a translucent one, and the grid covers most of the frame ten times a second.
     */
    static Color gridCell(int c) {
        return GRID_CELLS[c & 0xFF];
    }

    private <T> T newest(int robotId, String kind, Class<T> type) {
        Latest best = null;
        for (Latest l : context.stores().latest().ofKind(kind)) {
            if (l.robotId() == robotId && (best == null || l.version() > best.version())) {
                best = l;
            }
        }
        return best != null && type.isInstance(best.data()) ? type.cast(best.data()) : null;
    }

    private static String drawGrid(GraphicsContext g, Fumanoid.Grid grid, int fw, int fh, double ox, double oy,
                                   double scale, Set<Integer> classes) {
        int cols = grid.getColumns();
        int rows = grid.getRows();
        byte[] cells = grid.getCells().toByteArray();
        if (cols <= 0 || rows <= 0) {
            return " (no size)";
        }
        double cw = fw * scale / cols;
        double ch = fh * scale / rows;
        int n = Math.min(cells.length, cols * rows);
        for (int i = 0; i < n; i++) {
            int c = cells[i] & 0xFF;
            if (c == 0) {
                continue;
            }
            classes.add(c);
            g.setFill(gridCell(c));
            g.fillRect(ox + (i % cols) * cw, oy + (i / cols) * ch, cw, ch);
        }
        g.setFill(Color.gray(0.6, 0.25));
        for (int c = 1; c < cols; c++) {
            CrispLines.vertical(g, ox + c * cw, oy, oy + fh * scale);
        }
        for (int r = 1; r < rows; r++) {
            CrispLines.horizontal(g, ox, ox + fw * scale, oy + r * ch);
        }
        return n < cols * rows ? " (" + (cols * rows - n) + " cells missing)" : "";
    }

    private static void drawLegend(GraphicsContext g, Set<Integer> classes, double y, double w) {
        double x = 8;
        g.setLineWidth(2);
        g.setStroke(Color.DODGERBLUE);
        g.strokeRect(x, y, 12, 12);
        g.setFill(Color.LIGHTGRAY);
        g.fillText("frame", x + 16, y + 11);
        x += 60;
        g.setStroke(Color.RED);
        g.strokeRect(x, y, 12, 12);
        g.fillText("region", x + 16, y + 11);
        x += 64;
        for (int c : classes) {
            if (x > w - 60) {
                break;
            }
            g.setFill(ColorClasses.color(c));
            g.fillRect(x, y, 12, 12);
            g.setFill(Color.LIGHTGRAY);
            String name = ColorClasses.name(c);
            g.fillText(name, x + 16, y + 11);
            x += 24 + name.length() * 6.5;
        }
    }
}
