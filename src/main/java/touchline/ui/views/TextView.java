package touchline.ui.views;

import javafx.scene.control.TextArea;
import touchline.model.store.Latest;
import touchline.model.store.SequencedRing;
import touchline.model.store.TextLine;
import touchline.proto.Fumanoid;
import touchline.ui.SourcedView;
import touchline.ui.ViewContext;
import touchline.ui.ViewSource;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Set;

/** Plain text of one option: its newest {@link #LINES} lines, time-stamped. */
public final class TextView extends SourcedView {

    static final int LINES = 200;
    private final TextArea text = new TextArea();
    private final Deque<String> lines = new ArrayDeque<>();
    private long seenSeq;
    private ViewSource seenSource = ViewSource.NONE;

    public TextView(ViewContext context, ViewSource source) {
        super(context, Set.of(Fumanoid.DebugKind.TEXT_VALUE), source);
        text.setEditable(false);
        text.setId("option-text");
        text.setStyle("-fx-font-family: monospace;");
        root.setCenter(text);
    }

    @Override
    protected String draw(Latest latest) {
        ViewSource s = source();
        if (!s.equals(seenSource)) {
            seenSource = s;
            seenSeq = 0;
            lines.clear();
        }
        for (SequencedRing.Entry<TextLine> e : context.stores().text().since(seenSeq, s.robotId(), 5_000)) {
            if (e.value().option().equals(s.option())) {
                lines.addLast(DebugConsoleView.format(e.value()));
                if (lines.size() > LINES) {
                    lines.removeFirst();
                }
            }
        }
        seenSeq = context.stores().text().version();
        text.setText(String.join("\n", lines));
        text.positionCaret(text.getLength());
        return lines.size() + " lines";
    }
}
