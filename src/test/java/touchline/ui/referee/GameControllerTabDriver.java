package touchline.ui.referee;

import javafx.scene.Node;
import javafx.scene.Parent;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.TextField;

import java.net.DatagramSocket;
import touchline.ui.frame.ViewSource;
import touchline.ui.window.ConsoleWindowFixture;

/** Drives the GameController tab of a test window by program: no clicks by coordinates. */
public final class GameControllerTabDriver {

    private final ConsoleWindowFixture ui;
    private final Node tab;

    public GameControllerTabDriver(ConsoleWindowFixture ui) throws Exception {
        this.ui = ui;
        ui.fxRun(() -> ui.window.open("gamecontroller", ViewSource.NONE));
        this.tab = ui.fx(() -> ui.window.shell().openViews().stream().filter(v -> v.spec().id().equals("gamecontroller"))
                .findFirst().orElseThrow().view().node());
    }

    /**
     * Starts refereeing an HL game (hl12) towards {@code field} (a loopback socket standing in for
     * the robots): the tests written before the HSL tab drive its buttons.
     */
    public void start(DatagramSocket field) throws Exception {
        start(field, "hl12");
    }

    /** Starts refereeing in {@code format} (hsl20, hsl19, hl12 …) towards {@code field}. */
    public void start(DatagramSocket field, String format) throws Exception {
        start(field, format, true);
    }

    /** Presses Start; with {@code expectRunning} waits until the GameController runs. */
    @SuppressWarnings("unchecked")
    public void start(DatagramSocket field, String format, boolean expectRunning) throws Exception {
        ui.fxRun(() -> {
            ((javafx.scene.control.ComboBox<String>) tab.lookup("#gc-format")).setValue(format);
            ((TextField) tab.lookup("#gc-dest")).setText("127.0.0.1:" + field.getLocalPort());
            // return packets and monitor requests on OS-chosen ports: tests never bind the fixed 3939 or 3636
            ((TextField) tab.lookup("#gc-monitor-port")).setText("0");
            ((Parent) tab).lookupAll(".text-field").stream().map(n -> (TextField) n)
                    .filter(t -> "default".equals(t.getPromptText())).findFirst().orElseThrow().setText("0");
        });
        press("#gc-start");
        if (expectRunning) {
            ui.await(30, () -> ui.console.referee().gameController().isPresent());
            // the start runs off the FX thread: the tab shows the running GameController at a later frame
            ui.await(30, () -> tab.lookup("#gc-stop") != null);
        }
    }

    /** The tab's node, for reading its labels. */
    Node node() {
        return tab;
    }

    public void press(String id) throws Exception {
        ui.fxRun(() -> ((ButtonBase) tab.lookup(id)).fire());
    }
}
