package touchline.ui.views;

import javafx.scene.control.ListView;
import touchline.model.store.Latest;
import touchline.model.store.SequencedRing;
import touchline.model.store.TextLine;
import touchline.proto.Fumanoid;
import touchline.ui.SourcedView;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

/**
 * Plain text of one option: its newest {@link #LINES} lines, time-stamped, newest at the
 * bottom. A list (not a text area) so appending a line costs one cell, not a re-layout of all.
 */
public final class TextView extends SourcedView {

    static final int LINES = 500;
    private final ListView<String> lines = new ListView<>();
    private long seenSeq;
    private ViewSource seenSource = ViewSource.NONE;

    public TextView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.TEXT_VALUE), source);
        lines.setId("option-text");
        lines.setStyle("-fx-font-family: monospace;");
        lines.setFixedCellSize(22);
        root.setCenter(lines);
    }

    /** The lines shown (for tests). */
    public List<String> shownLines() {
        return List.copyOf(lines.getItems());
    }

    @Override
    protected String draw(Latest latest) {
        ViewSource s = source();
        if (!s.equals(seenSource)) {
            seenSource = s;
            seenSeq = 0;
            lines.getItems().clear();
        }
        List<String> add = new ArrayList<>();
        long v = context.stores().text().version();
        for (SequencedRing.Entry<TextLine> e : context.stores().text().since(seenSeq, s.robotId(), LINES)) {
            if (e.seq() <= v && e.value().option().equals(s.option())) {
                add.add(DebugConsoleView.format(e.value()));
            }
        }
        seenSeq = v;
        if (!add.isEmpty()) {
            lines.getItems().addAll(add);
            int over = lines.getItems().size() - LINES;
            if (over > 0) {
                lines.getItems().remove(0, over);
            }
            lines.scrollTo(lines.getItems().size() - 1);
        }
        return lines.getItems().size() + " lines";
    }
}
