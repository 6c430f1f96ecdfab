package touchline.ui.referee;

import javafx.scene.Scene;
import javafx.scene.control.Button;
import javafx.scene.control.TextField;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.testfx.api.FxToolkit;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.app.game.EmbeddedGameController;
import touchline.game.Game;
import touchline.game.LeagueParams;
import touchline.testing.Await;
import touchline.testing.HeldOwner;
import touchline.testing.UiTest;
import touchline.transport.Channel;
import touchline.transport.Direction;
import touchline.transport.UdpConfig;
import touchline.transport.gamecontroller.GcConfig;
import touchline.transport.gamecontroller.GcProfile;
import touchline.ui.window.ViewContext;
import touchline.ui.window.ViewRegistry;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import static org.junit.jupiter.api.Assertions.*;
import static touchline.testing.FxStep.fx;

/**
 * The GameController tab on a headless stage against a real UDP receiver standing in for a
 * robot: starting sends HL v12 packets, Play is sent at once and switches match mode on.
 */
@UiTest
class GameControllerTabTest {

    @BeforeAll
    static void toolkit() throws Exception {
        FxToolkit.registerPrimaryStage();
    }

    private static byte[] receive(DatagramSocket robot) throws Exception {
        DatagramPacket p = new DatagramPacket(new byte[2048], 2048);
        robot.receive(p);
        return java.util.Arrays.copyOf(p.getData(), p.getLength());
    }

    @Test
    void refereesAGameFromTheTab() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start(); DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            robot.setSoTimeout(5000);
            AtomicBoolean published = new AtomicBoolean();
            console.field().bus().subscribe(e -> {
                if (e.channel() == Channel.GAMECONTROLLER && e.direction() == Direction.OUT) {
                    published.set(true);
                }
            });
            GameControllerTab tab = tab(console, robot);
            fx(() -> {
                ((Button) tab.node().lookup("#gc-start")).fire();
                return null;
            });
            byte[] first = receive(robot);
            Await.until("the running GameController shown", () -> onFx(() -> {
                tab.refresh(null);
                return tab.node().lookup("#gc-ready") != null;
            }));
            assertEquals(688, first.length, "HL v12 as chosen");
            assertEquals('R', first[0]);
            assertEquals(0, first[9], "INITIAL");
            assertTrue(console.referee().gameController().isPresent());

            fx(() -> {
                ((Button) tab.node().lookup("#gc-ready")).fire();
                ((Button) tab.node().lookup("#gc-set")).fire();
                ((Button) tab.node().lookup("#gc-play")).fire();
                return null;
            });
            byte[] p;
            do {
                p = receive(robot);
            } while (p[9] != 3);
            assertTrue(console.referee().matchMode().playIsOn(), "our own GameController's PLAYING silences the console");
            assertTrue(published.get(), "sent packets appear in the Envelope stream");

            String outcome = console.referee().gameController().orElseThrow().sender().awaitRealtimeOutcome(5000);
            assertNotEquals(touchline.transport.gamecontroller.GcSender.NOT_REQUESTED, outcome, "the tab asks for real-time priority by default");
            fx(() -> {
                tab.refresh(null);
                String priority = ((javafx.scene.control.Label) tab.node().lookup("#gc-priority")).getText();
                // granted (root, CAP_SYS_NICE) or refused with the reason: the tab says which
                assertEquals(outcome.isEmpty(), priority.startsWith("Sender: real-time priority"), priority);
                assertEquals(!outcome.isEmpty(), priority.contains("real-time refused (" + outcome + ")"), priority);
                String notice = ((javafx.scene.control.Label) tab.node().lookup("#match-notice")).getText();
                assertTrue(notice.contains("game is PLAYING (this console's GameController)"), notice);
                assertTrue(notice.endsWith("held back since play began (retries included); 0 requests waiting now"), notice);
                return null;
            });

            // Stop only asks: with the game's thread held (so the runtime's close cannot end), the
            // FX thread comes back at once and the tab says "stopping…" until the close is done
            try (HeldOwner owner = new HeldOwner(console.referee().gameController().orElseThrow().runtime())) {
                fx(() -> {
                    ((Button) tab.node().lookup("#gc-undo")).fire(); // a change: the listener holds gc-game
                    return null;
                });
                assertTrue(owner.awaitHeld(), "the game's thread is held");
                String asked = fx(() -> {
                    ((Button) tab.node().lookup("#gc-stop")).fire();
                    tab.refresh(null);
                    return setupMessage(tab);
                });
                assertEquals("stopping…", asked, "Stop returned while the runtime's close was held");
                assertTrue(console.referee().gameController().isEmpty(), "no longer the running GameController");
            }
            Await.until("the stop done", () -> "stopped".equals(onFx(() -> {
                tab.refresh(null);
                return setupMessage(tab);
            })));
        }
    }

    @Test
    void startOnlyAsksWhileTheStopBeforeItIsHeld() throws Exception {
        ConsoleConfig config = ConsoleConfig.defaults().withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0));
        try (Console console = new Console(config).start(); DatagramSocket robot = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0))) {
            GameControllerTab tab = tab(console, robot);
            // a GameController started elsewhere with its game's thread held: the stop a start
            // begins with (which joins that thread) cannot end
            GcConfig elsewhereConfig = new GcConfig(GcProfile.HL12, false,
                    List.of(new InetSocketAddress("127.0.0.1", robot.getLocalPort())), null,
                    new InetSocketAddress("127.0.0.1", 0), null, GcConfig.INTERVAL_MS, false);
            EmbeddedGameController elsewhere = console.referee().start(
                    new Game(LeagueParams.hlSimulationKidSize(), 3, 1, 4, 0, console.referee().gameClock()), elsewhereConfig);
            try (HeldOwner owner = new HeldOwner(elsewhere.runtime())) {
                elsewhere.runtime().perform(new touchline.game.ToReady()); // a change: the listener holds gc-game
                assertTrue(owner.awaitHeld(), "the game's thread is held");
                String asked = fx(() -> {
                    ((Button) tab.node().lookup("#gc-start")).fire();
                    tab.refresh(null);
                    // the form is gone when Start waited for the stop and showed the running one
                    return tab.node().lookup("#gc-setup-message") == null ? "shown by Start itself" : setupMessage(tab);
                });
                assertEquals("starting…", asked, "Start returned while the stop before it was held");
            }
            Await.until("the started GameController shown", () -> onFx(() -> {
                tab.refresh(null);
                return tab.node().lookup("#gc-stop") != null;
            }));
            assertNotSame(elsewhere, console.referee().gameController().orElseThrow(), "the tab's own runs");
        }
    }

    /** The tab on its own scene, set up to send HL v12 to {@code robot}, returns on a port the system chooses. */
    @SuppressWarnings("unchecked")
    private static GameControllerTab tab(Console console, DatagramSocket robot) throws Exception {
        ViewContext context = new ViewContext(console.field(), console.optionSwitches(),
                console.referee(), console.naos(), console.recordings(), console.replays(), console.teamSchemas(),
                console.teamBudget(), console.remote(), console.bridges(), new ViewRegistry(), (s, src) -> { }, null,
                new touchline.ui.viewers.ServeToggle(console.serving()));
        return fx(() -> {
            GameControllerTab t = new GameControllerTab(context, null);
            new Scene((javafx.scene.Parent) t.node());
            ((TextField) t.node().lookup("#gc-dest")).setText("127.0.0.1:" + robot.getLocalPort());
            // hsl20 is the tab's default since the 2026 season; this test referees an HL game
            ((javafx.scene.control.ComboBox<String>) t.node().lookup("#gc-format")).setValue("hl12");
            // return packets on an OS-chosen port: tests never bind the fixed 3939
            ((TextField) ((javafx.scene.Parent) t.node()).lookupAll(".text-field").stream()
                    .filter(n -> "default".equals(((TextField) n).getPromptText())).findFirst().orElseThrow()).setText("0");
            return t;
        });
    }

    private static String setupMessage(GameControllerTab tab) {
        return ((javafx.scene.control.Label) tab.node().lookup("#gc-setup-message")).getText();
    }

    private static <T> T onFx(java.util.concurrent.Callable<T> step) {
        try {
            return fx(step);
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }
}
