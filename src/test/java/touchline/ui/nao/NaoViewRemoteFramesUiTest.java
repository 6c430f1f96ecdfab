package touchline.ui.nao;

import javafx.scene.Node;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.Label;
import javafx.scene.control.ToggleButton;
import javafx.scene.image.ImageView;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.UiTest;
import touchline.transport.Origin;
import touchline.transport.UdpConfig;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.LatencyProbe;

import java.net.URI;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.testing.FxStep.fx;

/**
 * The NAO tab on a console that views a remote Touchline (headless, Monocle): a camera frame
 * that arrives as an envelope is drawn though no camera was opened here, and the view's
 * commands are refused with the remote view's words.
 */
@UiTest
class NaoViewRemoteFramesUiTest {

    @Test
    void drawsAFrameThatArrivedAsAnEnvelopeAndRefusesCommands() throws Exception {
        FxToolkit.registerPrimaryStage();
        FrameContext frame = new FrameContext(new LatencyProbe());
        try (Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)))) {
            console.remote().view(new URI("ws://127.0.0.1:9/"), null); // nobody there: it only has to be a viewer
            NaoView view = fx(() -> new NaoView(console.naos()));
            Node root = view.node();
            ImageView image = (ImageView) root.lookup("#nao-image");
            fx(() -> {
                view.refresh(frame);
                return null;
            });
            assertNull(image.getImage());

            byte[] jpeg = touchline.testing.NaoCameraEnvelopes.jpeg(320, 240);
            console.field().bus().accept(touchline.testing.NaoCameraEnvelopes.frame(jpeg, console.field().clock().nowMicros(), Origin.REMOTE));
            fx(() -> {
                view.refresh(frame);
                return null;
            });
            assertNotNull(image.getImage(), "the remote frame is drawn");
            assertEquals(320, image.getImage().getWidth());
            assertEquals(240, image.getImage().getHeight());
            assertFalse(((ToggleButton) root.lookup("#nao-camera")).isSelected(), "no camera was opened here");
            assertTrue(console.naos().sessions().isEmpty());

            String result = fx(() -> {
                ((ButtonBase) root.lookup("#nao-stand")).fire();
                view.refresh(frame);
                return ((Label) root.lookup("#nao-result")).getText();
            });
            assertEquals(Console.COMMANDS_OFF, result);
            boolean connected = fx(() -> {
                ((ButtonBase) root.lookup("#nao-insecure")).fire();
                ((ButtonBase) root.lookup("#nao-connect")).fire();
                view.refresh(frame);
                return ((ToggleButton) root.lookup("#nao-connect")).isSelected();
            });
            assertFalse(connected, "a viewer does not connect to a NAO");
            assertTrue(console.naos().sessions().isEmpty());
            assertTrue(fx(() -> ((Label) root.lookup("#nao-state")).getText()).startsWith("viewing a remote Touchline"));
            fx(() -> {
                view.close();
                return null;
            });
        }
    }
}
