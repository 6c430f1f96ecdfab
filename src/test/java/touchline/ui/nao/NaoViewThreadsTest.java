package touchline.ui.nao;

import javafx.application.Platform;
import javafx.scene.Node;
import javafx.scene.control.ButtonBase;
import javafx.scene.control.ComboBox;
import javafx.scene.control.Label;
import javafx.scene.control.ListView;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.testing.Await;
import touchline.testing.UiTest;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.UdpConfig;
import touchline.transport.nao.FakeNaoRobot;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.LatencyProbe;

import java.util.Arrays;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static touchline.testing.FxStep.fx;

/**
 * The threading rule on the NAO tab (docs/architecture.md, "Threads"): a click only enqueues —
 * the link's own thread sends the call and runs the stream's subscribers for it, while the
 * window's thread goes on — and closing the tab never waits on the JavaFX thread for the link's
 * thread to stop. A subscriber of the console's stream holds the link's thread to show it.
 */
@UiTest
class NaoViewThreadsTest {

    private final FrameContext frame = new FrameContext(new LatencyProbe());

    private NaoView connected(Console console, FakeNaoRobot robot) throws Exception {
        NaoView view = fx(() -> new NaoView(console.naos()));
        Node root = view.node();
        fx(() -> {
            ((TextField) root.lookup("#nao-rpc-port")).setText(Integer.toString(robot.port()));
            ((TextField) root.lookup("#nao-cam-port")).setText("0");
            ((ButtonBase) root.lookup("#nao-insecure")).fire(); // the fake has no CURVE: an old robot side
            ((ButtonBase) root.lookup("#nao-connect")).fire();
            return null;
        });
        Await.until("the NAO online", () -> shown(view, "#nao-state").startsWith("online"));
        return view;
    }

    private String shown(NaoView view, String id) {
        try {
            return fx(() -> {
                view.refresh(frame);
                return ((Label) view.node().lookup(id)).getText();
            });
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    private static Console console() {
        return new Console(ConsoleConfig.defaults()
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0)));
    }

    @SuppressWarnings("unchecked")
    @Test
    void aClickOnlyEnqueuesTheLinksThreadSendsAndPublishesTheCall() throws Exception {
        FxToolkit.registerPrimaryStage();
        AtomicReference<String> publishedOn = new AtomicReference<>();
        CountDownLatch release = new CountDownLatch(1);
        try (FakeNaoRobot robot = new FakeNaoRobot(0); Console console = console()) {
            console.field().bus().subscribe(e -> {
                if (e.channel() == Channel.NAO_RPC && e.direction() == Direction.OUT && e.kind().equals("Test.void")) {
                    publishedOn.set(Thread.currentThread().getName());
                    awaitQuietly(release); // the stream's work for this call, held
                }
            });
            NaoView view = connected(console, robot);
            Node root = view.node();
            fx(() -> {
                ((ComboBox<String>) root.lookup("#nao-module")).setValue("Test");
                ((ButtonBase) root.lookup("#nao-discover")).fire();
                return null;
            });
            Await.until("the methods listed", () -> {
                try {
                    return fx(() -> {
                        view.refresh(frame);
                        return ((ListView<String>) root.lookup("#nao-methods")).getItems().contains("void");
                    });
                } catch (Exception e) {
                    return false;
                }
            });
            try {
                fx(() -> { // returns although the call's publishing is held: the click only enqueued it
                    ((ListView<String>) root.lookup("#nao-methods")).getSelectionModel().select("void");
                    ((TextField) root.lookup("#nao-params")).setText("");
                    ((ButtonBase) root.lookup("#nao-call")).fire();
                    return null;
                });
                Await.until("the call's request published", () -> publishedOn.get() != null);
                assertEquals(Boolean.TRUE, fx(() -> Boolean.TRUE), "the JavaFX thread runs while the stream works");
                assertTrue(publishedOn.get().startsWith("nao-link-"), "published on " + publishedOn.get());
            } finally {
                release.countDown();
            }
            Await.until("the call's outcome shown", () -> shown(view, "#nao-result").equals("Test.void: done"));
            fx(() -> {
                view.close();
                return null;
            });
        }
    }

    @Test
    void closingTheTabDoesNotWaitOnTheJavaFxThreadForTheLinkToStop() throws Exception {
        FxToolkit.registerPrimaryStage();
        Thread fxThread = fx(Thread::currentThread);
        AtomicReference<Boolean> fxRanWhileTheLinkStopped = new AtomicReference<>();
        CountDownLatch closing = new CountDownLatch(1);
        try (FakeNaoRobot robot = new FakeNaoRobot(0); Console console = console()) {
            console.field().bus().subscribe(e -> {
                if (e.channel() == Channel.LINK_EVENT && closing.getCount() == 0 && fxRanWhileTheLinkStopped.get() == null
                        && !Thread.currentThread().getName().equals(fxThread.getName())) {
                    // the link's thread, stopping: does the JavaFX thread run meanwhile, or wait for it?
                    CountDownLatch ran = new CountDownLatch(1);
                    Platform.runLater(ran::countDown);
                    try {
                        Await.until("the JavaFX thread runs or is seen waiting for a NAO thread",
                                () -> ran.getCount() == 0 || waitsForANaoThread(fxThread));
                    } catch (InterruptedException interrupted) {
                        Thread.currentThread().interrupt();
                    }
                    fxRanWhileTheLinkStopped.set(ran.getCount() == 0);
                }
            });
            NaoView view = connected(console, robot);
            closing.countDown();
            fx(() -> {
                view.close();
                return null;
            });
            Await.until("the link's thread stopped and told", () -> fxRanWhileTheLinkStopped.get() != null);
            assertTrue(fxRanWhileTheLinkStopped.get(), "the JavaFX thread waited for the NAO link's thread to stop");
        }
    }

    /** Whether {@code fx} is inside a NAO link's or camera's close, waiting for its thread. */
    private static boolean waitsForANaoThread(Thread fx) {
        return Arrays.stream(fx.getStackTrace()).anyMatch(f -> f.getClassName().startsWith("touchline.transport.nao.")
                && f.getMethodName().equals("close"))
                && Arrays.stream(fx.getStackTrace()).anyMatch(f -> f.getClassName().equals(Thread.class.getName())
                && f.getMethodName().equals("join"));
    }

    private static void awaitQuietly(CountDownLatch latch) {
        try {
            latch.await(Await.FLOOR_MILLIS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
