package touchline.ui.consoles;

import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.ListCell;
import javafx.scene.text.Text;
import javafx.scene.text.TextFlow;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;

/**
 * A list line with every match of the search highlighted ({@code .search-hit}, case
 * ignored); a plain text line when there is no search. Only the visible cells build nodes.
 */
final class SearchHitCell extends ListCell<String> {

    private final Supplier<String> needle;

    SearchHitCell(Supplier<String> needle) {
        this.needle = needle;
    }

    @Override
    protected void updateItem(String line, boolean empty) {
        super.updateItem(line, empty);
        String n = needle.get() == null ? "" : needle.get();
        if (empty || line == null) {
            setText(null);
            setGraphic(null);
        } else if (n.isEmpty() || !line.toLowerCase(Locale.ROOT).contains(n.toLowerCase(Locale.ROOT))) {
            setText(line);
            setGraphic(null);
        } else {
            setText(null);
            TextFlow flow = new TextFlow(parts(line, n).toArray(Node[]::new));
            flow.getStyleClass().add("search-line");
            setGraphic(flow);
        }
    }

    /** The line cut into plain text and highlighted matches. */
    static List<Node> parts(String line, String needle) {
        List<Node> out = new ArrayList<>();
        String lower = line.toLowerCase(Locale.ROOT);
        String n = needle.toLowerCase(Locale.ROOT);
        int from = 0;
        for (int hit = lower.indexOf(n); hit >= 0 && !n.isEmpty(); hit = lower.indexOf(n, hit + n.length())) {
            if (hit > from) {
                out.add(plain(line.substring(from, hit)));
            }
            Label mark = new Label(line.substring(hit, hit + n.length()));
            mark.getStyleClass().add("search-hit");
            out.add(mark);
            from = hit + n.length();
        }
        if (from < line.length()) {
            out.add(plain(line.substring(from)));
        }
        return out;
    }

    private static Text plain(String s) {
        Text t = new Text(s);
        t.getStyleClass().add("text");
        return t;
    }
}
