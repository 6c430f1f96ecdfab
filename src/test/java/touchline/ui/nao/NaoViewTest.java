package touchline.ui.nao;

import javafx.scene.Node;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import javafx.scene.image.ImageView;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import org.testfx.util.WaitForAsyncUtils;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.UiTest;
import touchline.transport.UdpConfig;
import touchline.transport.Channel;
import touchline.transport.Envelope;
import touchline.transport.nao.FakeNaoCamera;
import touchline.transport.nao.FakeNaoRobot;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.LatencyProbe;

import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/**
 * The NAO tab headless (Monocle) against the in-test robot and camera stand-ins, connected
 * through an (unstarted: no GameController heard, so match mode is off) application core.
 */
@UiTest
class NaoViewTest {

    @SuppressWarnings("unchecked")
    @Test
    void connectsDiscoversCallsAndShowsTheCamera() throws Exception {
        FxToolkit.registerPrimaryStage();
        List<Envelope> envelopes = new CopyOnWriteArrayList<>();
        FrameContext frame = new FrameContext(new LatencyProbe());
        try (FakeNaoRobot robot = new FakeNaoRobot(0); FakeNaoCamera camera = new FakeNaoCamera();
             Console console = new Console(ConsoleConfig.defaults()
                     .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)))) {
            console.field().bus().subscribe(envelopes::add);
            NaoView view = fx(() -> new NaoView(console.naos()));
            Node root = view.node();
            fx(() -> {
                ((TextField) root.lookup("#nao-rpc-port")).setText(Integer.toString(robot.port()));
                ((TextField) root.lookup("#nao-cam-port")).setText(Integer.toString(camera.port()));
                ((ButtonBase) root.lookup("#nao-camera")).fire();
                ((ButtonBase) root.lookup("#nao-insecure")).fire(); // the fakes have no CURVE: an old robot side
                ((ButtonBase) root.lookup("#nao-connect")).fire();
                return null;
            });
            Callable<Boolean> online = () -> {
                view.refresh(frame);
                return ((Label) root.lookup("#nao-state")).getText().startsWith("online");
            };
            WaitForAsyncUtils.waitFor(30, TimeUnit.SECONDS, () -> fx(online));
            fx(() -> {
                ((ComboBox<String>) root.lookup("#nao-module")).setValue("Test");
                ((ButtonBase) root.lookup("#nao-discover")).fire();
                return null;
            });
            WaitForAsyncUtils.waitFor(30, TimeUnit.SECONDS, () -> fx(() -> {
                view.refresh(frame);
                return ((ListView<String>) root.lookup("#nao-methods")).getItems().contains("echo");
            }));
            fx(() -> {
                ((ListView<String>) root.lookup("#nao-methods")).getSelectionModel().select("echo");
                ((TextField) root.lookup("#nao-params")).setText("[a, 1]");
                ((ButtonBase) root.lookup("#nao-call")).fire();
                return null;
            });
            WaitForAsyncUtils.waitFor(30, TimeUnit.SECONDS, () -> fx(() -> {
                view.refresh(frame);
                return ((Label) root.lookup("#nao-result")).getText().equals("Test.echo: [\"a\", 1]");
            }));
            WaitForAsyncUtils.waitFor(30, TimeUnit.SECONDS, () -> fx(() -> {
                view.refresh(frame);
                return ((ImageView) root.lookup("#nao-image")).getImage() != null;
            }));
            fx(() -> {
                view.close();
                return null;
            });
        }
        assertTrue(envelopes.stream().anyMatch(e -> e.channel() == Channel.NAO_CAMERA));
        assertTrue(envelopes.stream().anyMatch(e -> e.channel() == Channel.NAO_RPC && e.kind().equals("Test.echo")));
    }
}
