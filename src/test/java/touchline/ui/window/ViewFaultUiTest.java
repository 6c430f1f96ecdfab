package touchline.ui.window;

import javafx.beans.property.ReadOnlyObjectWrapper;
import javafx.scene.Node;
import javafx.scene.control.Label;
import javafx.scene.control.TableColumn;
import javafx.scene.control.TableRow;
import javafx.scene.control.TableView;
import javafx.scene.control.TextField;
import javafx.scene.control.ToggleButton;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import touchline.testing.RobotProcess;
import touchline.testing.UiTest;
import touchline.transport.Envelope;

import java.net.DatagramPacket;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.util.List;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import touchline.ui.frame.FrameContext;
import touchline.ui.frame.View;
import touchline.ui.frame.ViewFrame;
import touchline.ui.frame.ViewSource;

/**
 * A fault in one view stays in that view: the reason is shown inside it, and the network
 * console next to it keeps showing the newest datagrams (real datagrams on loopback).
 */
@UiTest
class ViewFaultUiTest {

    private ConsoleWindowFixture ui;
    private DatagramSocket sender;
    private int sent;

    @BeforeEach
    void open() throws Exception {
        sender = new DatagramSocket(new InetSocketAddress("127.0.0.1", 0));
        ui.fxRun(() -> {
            ui.window.shell().restore(List.of());
            ui.window.open("network", ViewSource.NONE);
        });
    }

    @AfterEach
    void close() throws Exception {
        sender.close();
    }

    /** A view whose refresh throws while {@code broken} is set. */
    private static final class BrokenRefresh implements View {
        volatile boolean broken = true;
        private final Label label = new Label("fine");

        @Override
        public Node node() {
            return label;
        }

        @Override
        public void refresh(FrameContext frame) {
            if (broken) {
                throw new IllegalStateException("refresh broken on purpose");
            }
            label.setText("fine again");
        }
    }

    /** A table whose cells throw while they are laid out (as the NAO's unresolved peer once did). */
    private static final class BrokenCells implements View {
        private final TableView<String> table = new TableView<>();
        private final boolean bad;

        BrokenCells(boolean bad) {
            this.bad = bad;
            TableColumn<String, String> c = new TableColumn<>("Value");
            c.setCellValueFactory(cell -> {
                if (cell.getValue().startsWith("bad")) {
                    throw new NullPointerException("cell broken on purpose");
                }
                return new ReadOnlyObjectWrapper<>(cell.getValue());
            });
            table.getColumns().add(c);
        }

        @Override
        public Node node() {
            return table;
        }

        @Override
        public void refresh(FrameContext frame) {
            if (table.getItems().size() < 3) {
                table.getItems().add(table.getItems().size() < 2 || !bad ? "good" : "bad");
            }
        }
    }

    private static ViewSpec spec(String id, View view) {
        return new ViewSpec(id, "Broken " + id, "a view that fails", Set.of(), (c, s) -> view);
    }

    private void sendDatagram() throws Exception {
        byte[] b = ("not a robot message " + (++sent)).getBytes();
        sender.send(new DatagramPacket(b, b.length, InetAddress.getLoopbackAddress(), ui.port()));
    }

    /** True when the network table's rows on screen include its newest envelope from our sender. */
    @SuppressWarnings("unchecked")
    private boolean networkShowsNewest() {
        TableView<Envelope> table = ui.robot.lookup("#network-table").queryAs(TableView.class);
        if (table.getItems().isEmpty()) {
            return false;
        }
        Envelope newest = table.getItems().get(table.getItems().size() - 1);
        String text = new String(newest.raw());
        return text.equals("not a robot message " + sent)
                && ui.robot.from(table).lookup(".table-row-cell").<TableRow<Envelope>>queryAll().stream()
                .anyMatch(r -> r.getItem() == newest && r.isVisible() && !r.isEmpty());
    }

    private ViewFrame frameOf(View view) throws Exception {
        return ui.fx(() -> ui.window.shell().openViews().stream().filter(v -> v.view() == view)
                .map(Shell.OpenView::frame).findFirst().orElseThrow());
    }

    @Test
    void aViewWhoseRefreshThrowsShowsTheReasonAndTheOthersGoOn() throws Exception {
        BrokenRefresh broken = new BrokenRefresh();
        ui.fxRun(() -> ui.window.shell().open(spec("refresh", broken), ViewSource.NONE));
        ViewFrame frame = frameOf(broken);
        ui.await(30, () -> frame.fault().contains("refresh broken on purpose"));
        assertTrue(ui.fx(() -> ui.robot.from(frame).lookup(".view-fault").queryLabeled().isVisible()));
        ui.fxRun(() -> ui.window.open("network", ViewSource.NONE));
        for (int i = 0; i < 3; i++) {
            sendDatagram();
            ui.await(30, this::networkShowsNewest);
        }
        ui.fxRun(() -> ui.window.shell().open(spec("refresh", broken), ViewSource.NONE));
        assertTrue(ui.fx(() -> frame.fault().contains("refresh broken on purpose")), "shown until it works again");
        broken.broken = false;
        ui.await(30, () -> frame.fault().isEmpty() && ((Label) broken.node()).getText().equals("fine again"));
    }

    @Test
    void aViewWhoseCellsThrowStopsAloneUntilReopened() throws Exception {
        // JavaFX hands some cell faults to the thread's uncaught-exception handler as well; TestFX would
        // rethrow those in the test thread
        org.testfx.util.WaitForAsyncUtils.autoCheckException = false;
        try {
            cellsThrow();
        } finally {
            org.testfx.util.WaitForAsyncUtils.clearExceptions();
            org.testfx.util.WaitForAsyncUtils.autoCheckException = true;
        }
    }

    private void cellsThrow() throws Exception {
        sendDatagram();
        ui.await(30, this::networkShowsNewest);
        BrokenCells broken = new BrokenCells(true);
        int[] made = {0};
        ViewSpec cells = new ViewSpec("cells", "Broken cells", "a view that fails", Set.of(),
                (c, s) -> made[0]++ == 0 ? broken : new BrokenCells(false));
        ui.fxRun(() -> ui.window.shell().open(cells, ViewSource.NONE));
        ViewFrame frame = frameOf(broken);
        ui.await(30, () -> frame.stopped() && frame.fault().contains("cell broken on purpose"));
        // the network console is in the same dock: it must go on laying out its newest rows
        ui.fxRun(() -> ui.window.open("network", ViewSource.NONE));
        for (int i = 0; i < 3; i++) {
            sendDatagram();
            ui.await(30, this::networkShowsNewest);
        }
        assertTrue(ui.fx(frame::stopped), "a stopped view stays stopped until reopened");

        ui.fxRun(() -> ui.window.shell().open(cells, ViewSource.NONE));
        ui.fxRun(() -> ((javafx.scene.control.Button) frame.lookup(".view-reopen")).fire());
        ui.await(30, () -> !frame.stopped() && frame.fault().isEmpty()
                && ui.robot.from(frame).lookup(".table-row-cell").<TableRow<String>>queryAll().stream()
                .filter(r -> !r.isEmpty()).count() == 3);
    }

    @Test
    void aNaoWithEveryViewOpenShowsInTheNetworkConsole() throws Exception {
        touchline.testing.Requirement.robotSide("touchline-nao-sim");
        ui.fxRun(() -> {
            for (ViewSpec s : ui.window.registry().all()) {
                ui.window.shell().open(s, ViewSource.NONE);
            }
        });
        // The NAO's envelopes reach the console's bus exactly as the NAO view sends them (the
        // view's own connect button is NaoViewTest's business): with every view open, the
        // network console renders their peers (unresolved addresses: the NullPointerException
        // that froze the window).
        try (RobotProcess nao = RobotProcess.of(List.of(RobotProcess.binDir().resolve("touchline-nao-sim").toString(),
                "--bind", "127.0.0.1", "--rpc-port", "0", "--cam-port", "0")).start();
             touchline.transport.nao.NaoLink link = new touchline.transport.nao.NaoLink("127.0.0.1", nao.port(),
                     touchline.transport.nao.NaoLinkConfig.defaults(),
                     new touchline.transport.nao.NaoEnvelopeChannel(ui.console.field().bus()), null,
                     new touchline.app.SystemClock(), new touchline.app.SystemClock()).start()) {
            touchline.testing.Await.until("the NAO online", () -> link.state() == touchline.transport.nao.ConnectionState.ONLINE);
            link.call("ALMotion", "ping").get(30, java.util.concurrent.TimeUnit.SECONDS);
            ui.fxRun(() -> ui.window.open("network", ViewSource.NONE));
            String peer = "127.0.0.1:" + nao.port();
            ui.await(30, () -> ui.robot.lookup("#network-table").lookup(".table-cell").queryAll().stream()
                    .anyMatch(c -> c instanceof javafx.scene.control.TableCell<?, ?> cell && peer.equals(cell.getText())
                            && cell.getTableRow() != null && cell.getTableRow().getItem() instanceof Envelope e
                            && e.peer().isUnresolved()));
            List<String> faults = ui.fx(() -> ui.window.shell().openViews().stream()
                    .map(v -> v.frame().fault()).filter(f -> !f.isEmpty()).toList());
            assertEquals(List.of(), faults);
            assertFalse(ui.fx(() -> ui.window.shell().openViews().stream().anyMatch(v -> v.frame().stopped())));
        }
    }
}
