package touchline.ui.render;

import touchline.model.store.PlotStore;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A plot's y axes: one per unit of its series, so millimetres and a battery's percent do not
 * share a scale, or one per series on request. The unit is read from the field's name (a wire
 * descriptor carries no units): {@code …_mm} / {@code …Mm} millimetres, {@code …Percent} /
 * {@code …_pct} / battery percent, {@code …_deg} degrees, {@code …_rad} radians, {@code …_ms}
 * milliseconds. Series of no known unit share one axis of their own; when no series has a
 * unit there is one axis, as before units were read. Each axis is fitted to its series' values
 * in the window (5 % margin).
 */
final class YAxes {

    /** One y axis: its unit ("" when none is known) and its range, padded. */
    record Axis(String unit, double y0, double y1) {
        /** A tick label with the unit. */
        String label(String value) {
            return unit.isEmpty() ? value : value + " " + unit;
        }
    }

    private final List<Axis> axes = new ArrayList<>();
    private final int[] axisOf;

    /**
     * @param starts each series' first index inside the window
     * @param perSeries one axis per series rather than per unit
     */
    YAxes(List<PlotStore.SeriesData> series, int[] starts, boolean perSeries) {
        axisOf = new int[series.size()];
        Map<String, Integer> index = new LinkedHashMap<>();
        List<double[]> ranges = new ArrayList<>();
        List<String> units = new ArrayList<>();
        for (int k = 0; k < series.size(); k++) {
            PlotStore.SeriesData d = series.get(k);
            String unit = unitOf(d.name());
            int axis = index.computeIfAbsent(perSeries ? k + "\u0000" + unit : unit, key -> {
                ranges.add(new double[]{Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY});
                units.add(unit);
                return ranges.size() - 1;
            });
            double[] range = ranges.get(axis);
            for (int i = starts[k]; i < d.count(); i++) {
                double y = d.y()[i];
                if (Double.isFinite(y)) {
                    range[0] = Math.min(range[0], y);
                    range[1] = Math.max(range[1], y);
                }
            }
            axisOf[k] = axis;
        }
        for (int a = 0; a < ranges.size(); a++) {
            double min = ranges.get(a)[0];
            double max = ranges.get(a)[1];
            if (!(min <= max)) {
                min = -1;
                max = 1;
            }
            double pad = Math.max(1e-3, (max - min) * 0.05);
            axes.add(new Axis(units.get(a), min - pad, max + pad));
        }
        if (axes.isEmpty()) {
            axes.add(new Axis("", -1 - 0.1, 1 + 0.1));
        }
    }

    int count() {
        return axes.size();
    }

    Axis axis(int i) {
        return axes.get(i);
    }

    /** The axis the series at {@code series} is drawn against. */
    Axis of(int series) {
        return axes.get(axisOf[series]);
    }

    /** The unit a series' name tells ("" when it tells none): its last path segment's suffix. */
    static String unitOf(String name) {
        String field = name.substring(Math.max(Math.max(name.lastIndexOf(':'), name.lastIndexOf('.')),
                name.lastIndexOf(' ')) + 1);
        String lower = field.toLowerCase(Locale.ROOT);
        if (lower.equals("mm") || lower.endsWith("_mm") || field.endsWith("Mm")) {
            return "mm";
        }
        if (lower.contains("percent") || lower.endsWith("_pct") || field.endsWith("Pct") || lower.startsWith("battery")) {
            return "%";
        }
        if (lower.endsWith("_deg") || field.endsWith("Deg")) {
            return "°";
        }
        if (lower.endsWith("_rad") || field.endsWith("Rad")) {
            return "rad";
        }
        if (lower.endsWith("_ms") || field.endsWith("Ms")) {
            return "ms";
        }
        return "";
    }
}
