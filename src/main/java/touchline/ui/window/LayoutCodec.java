package touchline.ui.window;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads and writes layouts as indented text, one node per line:
 * <pre>
 * touchline-layout 1
 * window
 *  branch horizontal 0.35
 *   leaf 0
 *    view robots
 *    view plot 3/demo.plotter
 * </pre>
 * Reading is lenient: lines it does not understand are skipped, so a layout written by a
 * newer version, or hand-edited, still opens as far as it can.
 */
public final class LayoutCodec {

    static final String HEADER = "touchline-layout 1";

    /** The first window is the main one; further ones were detached windows. */
    public String write(List<LayoutNode> windows) {
        StringBuilder out = new StringBuilder(HEADER).append('\n');
        for (LayoutNode w : windows) {
            out.append("window\n");
            write(out, w, 1);
        }
        return out.toString();
    }

    private void write(StringBuilder out, LayoutNode node, int depth) {
        String indent = " ".repeat(depth);
        if (node instanceof LayoutNode.Branch b) {
            out.append(indent).append("branch ").append(b.vertical() ? "vertical" : "horizontal");
            for (double d : b.dividers()) {
                out.append(' ').append(String.format(Locale.ROOT, "%.4f", d));
            }
            out.append('\n');
            for (LayoutNode c : b.children()) {
                write(out, c, depth + 1);
            }
        } else if (node instanceof LayoutNode.Leaf l) {
            out.append(indent).append("leaf ").append(l.selected()).append('\n');
            for (LayoutNode.Entry e : l.views()) {
                out.append(indent).append(" view ").append(e.viewId());
                if (e.source() != null && !e.source().isEmpty()) {
                    out.append(' ').append(e.source());
                }
                out.append('\n');
            }
        }
    }

    public List<LayoutNode> read(String text) {
        List<Line> lines = new ArrayList<>();
        for (String raw : text.split("\n")) {
            String t = raw.strip();
            if (t.isEmpty() || t.startsWith("#") || t.startsWith("touchline-layout")) {
                continue;
            }
            lines.add(new Line(raw.length() - raw.stripLeading().length(), t.split("\\s+", 3)));
        }
        List<LayoutNode> windows = new ArrayList<>();
        int[] at = {0};
        while (at[0] < lines.size()) {
            Line l = lines.get(at[0]);
            at[0]++;
            if (l.words[0].equals("window")) {
                LayoutNode n = parseChildOf(lines, at, l.indent);
                if (n != null) {
                    windows.add(n);
                }
            }
        }
        return windows;
    }

    private record Line(int indent, String[] words) { }

    /** Parses the first node indented deeper than {@code parentIndent}, with its children. */
    private LayoutNode parseChildOf(List<Line> lines, int[] at, int parentIndent) {
        while (at[0] < lines.size() && lines.get(at[0]).indent > parentIndent) {
            Line l = lines.get(at[0]);
            at[0]++;
            switch (l.words[0]) {
                case "branch" -> {
                    boolean vertical = l.words.length > 1 && l.words[1].equals("vertical");
                    List<Double> dividers = new ArrayList<>();
                    if (l.words.length > 2) {
                        for (String d : l.words[2].split("\\s+")) {
                            try {
                                dividers.add(Double.parseDouble(d));
                            } catch (NumberFormatException ignored) {
                                // a bad divider only loses that divider's position
                            }
                        }
                    }
                    List<LayoutNode> children = new ArrayList<>();
                    while (at[0] < lines.size() && lines.get(at[0]).indent > l.indent) {
                        LayoutNode c = parseChildOf(lines, at, l.indent);
                        if (c != null) {
                            children.add(c);
                        }
                    }
                    return new LayoutNode.Branch(vertical, dividers, children);
                }
                case "leaf" -> {
                    int selected = 0;
                    try {
                        selected = l.words.length > 1 ? Integer.parseInt(l.words[1]) : 0;
                    } catch (NumberFormatException ignored) {
                        // keep the first tab selected
                    }
                    List<LayoutNode.Entry> views = new ArrayList<>();
                    while (at[0] < lines.size() && lines.get(at[0]).indent > l.indent) {
                        Line v = lines.get(at[0]);
                        at[0]++;
                        if (v.words[0].equals("view") && v.words.length > 1) {
                            views.add(new LayoutNode.Entry(v.words[1], v.words.length > 2 ? v.words[2] : ""));
                        }
                    }
                    return new LayoutNode.Leaf(selected, views);
                }
                default -> {
                    // unknown node: skip it and whatever is nested below it
                    while (at[0] < lines.size() && lines.get(at[0]).indent > l.indent) {
                        at[0]++;
                    }
                }
            }
        }
        return null;
    }
}
