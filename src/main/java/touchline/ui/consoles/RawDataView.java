package touchline.ui.consoles;

import javafx.scene.control.TextArea;
import touchline.model.store.Latest;
import touchline.protocol.MessageText;
import touchline.ui.frame.SourcedView;
import touchline.ui.window.ViewContext;
import touchline.ui.frame.ViewSource;

import java.util.Set;

/**
 * For options whose data kind no visualisation knows: the newest message as protobuf text,
 * field by field, so the data is still visible.
 */
public final class RawDataView extends SourcedView {

    private final TextArea text = new TextArea();
    private final MessageText render = new MessageText();

    public RawDataView(ViewContext context, ViewSource source) {
        super(context.field(), Set.of(), source);
        text.setEditable(false);
        text.setId("raw-text");
        text.setStyle("-fx-font-family: monospace;");
        root.setCenter(text);
    }

    @Override
    protected String draw(Latest latest) {
        text.setText(render.render(latest.data()));
        return "unknown data kind: shown as protobuf text (" + latest.kind() + ")";
    }
}
