package touchline.ui.consoles;

import javafx.scene.control.ListView;
import touchline.model.store.Latest;
import touchline.model.store.SequencedRing;
import touchline.model.store.TextLine;
import touchline.proto.Fumanoid;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.Set;

/**
 * Plain text of one option: its newest {@link #LINES} lines, time-stamped, newest at the
 * bottom. A list (not a text area) so appending a line costs one cell, not a re-layout of all.
 */
public final class TextView extends SourcedView {

    static final int LINES = 500;
    private final ListView<String> lines = new ListView<>();
    private final RingFollower<TextLine, String> follower = new RingFollower<>(lines.getItems(), LINES);
    private ViewSource seenSource = ViewSource.NONE;

    public TextView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(Fumanoid.DebugKind.TEXT_VALUE), source);
        lines.setId("option-text");
        lines.setStyle("-fx-font-family: monospace;");
        lines.setFixedCellSize(22);
        root.setCenter(lines);
    }

    @Override
    protected String draw(Latest latest) {
        ViewSource s = source();
        if (!s.equals(seenSource)) {
            seenSource = s;
            follower.reload();
        }
        SequencedRing.Entry<TextLine> newest = follower.follow(stores().text().version(),
                (after, max) -> stores().text().since(after, s.robotId(), max),
                l -> l.option().equals(s.option()) ? DebugConsoleView.format(l) : null);
        if (newest != null && follower.added() > 0) {
            lines.scrollTo(lines.getItems().size() - 1);
        }
        return lines.getItems().size() + " lines";
    }
}
