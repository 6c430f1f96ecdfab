package touchline.ui.field;

import javafx.scene.paint.Color;
import touchline.model.store.Latest;
import touchline.proto.Fumanoid;
import touchline.ui.render.RasterPane;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.Set;
import java.util.TreeSet;
import touchline.ui.render.ColorClasses;
import touchline.ui.render.CrispLines;
import touchline.ui.render.LabelSprites;
import touchline.ui.render.Raster;

/**
 * The HaViMo2 camera's view: the whole frame as a blue rectangle, each region-growing blob as
 * a red rectangle filled in its colour class, the gridding result as translucent cells, and a
 * legend. Regions reaching outside the frame are clipped to it and drawn dashed; the status
 * line counts them. Drawn into pixels of its own ({@link Raster}) each time the regions or the
 * grid change: ten to twenty times a second with the demo robots.
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
    private static final int BACKGROUND_ARGB = Raster.opaque(BACKGROUND);
    private static final int GRID_LINE_ARGB = Raster.opaque(Color.gray(0.6));
    private static final double GRID_LINE_OPACITY = 0.25;
    private static final double REGION_OPACITY = 0.35;
    private static final int REGION_LINE_ARGB = Raster.opaque(Color.RED);
    private static final int FRAME_LINE_ARGB = Raster.opaque(Color.DODGERBLUE);
    private static final Color LEGEND_TEXT = Color.LIGHTGRAY;
    private final RasterPane pane = new RasterPane(() -> dirty = true);
    private final Raster raster = new Raster();
    private final LabelSprites labels = new LabelSprites(javafx.scene.text.Font.getDefault());

    public RegionOverlayView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.REGION_GROWING_VALUE, Fumanoid.DebugKind.GRID_VALUE), source);
        pane.setId("region-canvas");
        root.setCenter(pane);
    }

    @Override
    protected void empty() {
        raster.begin(pane, BACKGROUND_ARGB);
        raster.show(pane);
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
        double w = pane.getWidth();
        double h = pane.getHeight();
        raster.begin(pane, BACKGROUND_ARGB);
        double legend = 24;
        double margin = 24;
        double scale = Math.max(0.01, Math.min((w - 2 * margin) / fw, (h - 2 * margin - legend) / fh));
        double ox = (w - fw * scale) / 2;
        double oy = margin;
        Set<Integer> classes = new TreeSet<>();
        String gridNote = "";
        if (grid != null) {
            gridNote = drawGrid(grid, fw, fh, ox, oy, scale, classes);
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
                double rx = ox + cx1 * scale;
                double ry = oy + cy1 * scale;
                double rw = (cx2 - cx1) * scale;
                double rh = (cy2 - cy1) * scale;
                raster.blendRect(rx, ry, rw, rh, Raster.opaque(ColorClasses.color(r.getColorClass())), REGION_OPACITY);
                if (wasClipped) {
                    raster.dashedOutline(rx, ry, rw, rh, 2, 6, 4, REGION_LINE_ARGB);
                } else {
                    raster.outline(rx, ry, rw, rh, 2, REGION_LINE_ARGB);
                }
                if (wasClipped) {
                    clipped++;
                }
                shown++;
            }
        }
        raster.outline(ox - 1, oy - 1, fw * scale + 2, fh * scale + 2, 2, FRAME_LINE_ARGB);
        drawLegend(classes, h - legend + 4, w);
        raster.show(pane);
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
        for (Latest l : stores().latest().ofKind(kind)) {
            if (l.robotId() == robotId && (best == null || l.version() > best.version())) {
                best = l;
            }
        }
        return best != null && type.isInstance(best.data()) ? type.cast(best.data()) : null;
    }

    private String drawGrid(Fumanoid.Grid grid, int fw, int fh, double ox, double oy,
                                   double scale, Set<Integer> classes) {
        int cols = grid.getColumns();
        int rows = grid.getRows();
        byte[] cells = grid.getCells().toByteArray();
        if (cols <= 0 || rows <= 0) {
            return " (no size)";
        }
        CrispLines.Fill gridLine = (x, y, w, h) -> raster.blendRect(x, y, w, h, GRID_LINE_ARGB, GRID_LINE_OPACITY);
        double cw = fw * scale / cols;
        double ch = fh * scale / rows;
        int n = Math.min(cells.length, cols * rows);
        for (int i = 0; i < n; i++) {
            int c = cells[i] & 0xFF;
            if (c == 0) {
                continue;
            }
            classes.add(c);
            raster.fillRect(ox + (i % cols) * cw, oy + (i / cols) * ch, cw, ch, Raster.opaque(gridCell(c)));
        }
        for (int c = 1; c < cols; c++) {
            CrispLines.vertical(gridLine, ox + c * cw, oy, oy + fh * scale);
        }
        for (int r = 1; r < rows; r++) {
            CrispLines.horizontal(gridLine, ox, ox + fw * scale, oy + r * ch);
        }
        return n < cols * rows ? " (" + (cols * rows - n) + " cells missing)" : "";
    }

    private void drawLegend(Set<Integer> classes, double y, double w) {
        double x = 8;
        raster.outline(x - 1, y - 1, 14, 14, 2, FRAME_LINE_ARGB);
        legendText("frame", x + 16, y);
        x += 60;
        raster.outline(x - 1, y - 1, 14, 14, 2, REGION_LINE_ARGB);
        legendText("region", x + 16, y);
        x += 64;
        for (int c : classes) {
            if (x > w - 60) {
                break;
            }
            raster.fillRect(x, y, 12, 12, Raster.opaque(ColorClasses.color(c)));
            String name = ColorClasses.name(c);
            legendText(name, x + 16, y);
            x += 24 + name.length() * 6.5;
        }
    }

    /** A legend entry's name right of its 12-pixel square at ({@code x}, {@code y}), centred on it. */
    private void legendText(String name, double x, double y) {
        Raster.Sprite s = labels.of(name, LEGEND_TEXT, raster.scale());
        raster.draw(s, x, y + 6 - s.height() / raster.scale() / 2);
    }
}
