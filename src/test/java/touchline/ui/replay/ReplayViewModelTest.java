package touchline.ui.replay;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import touchline.app.Console;
import touchline.app.ConsoleConfig;
import touchline.record.PlayerState;
import touchline.record.ReplayNotes;
import touchline.record.TimelineEvent;
import touchline.testing.Await;
import touchline.transport.UdpConfig;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.*;

/** The Replay view's decisions without JavaFX: what it opens or refuses, the loop marks, the lines it shows. */
@Tag("integration")
class ReplayViewModelTest {

    private static PlayerState at(long position, boolean playing, long loopFrom, long loopTo) {
        return new PlayerState(position, 1_000_000, 61_000_000, playing, false, 2.5, loopFrom, loopTo, 12_345,
                ReplayNotes.NONE);
    }

    @Test
    void opensTheTypedRecordingAndRefusesAnEmptyField() throws Exception {
        assertEquals(Optional.of("Type or choose a recording to open."), ReplayViewModel.refusal("  "));
        String sample = Path.of("samples/demo-team.mcap").toAbsolutePath().toString();
        assertEquals(Optional.empty(), ReplayViewModel.refusal(sample));
        try (Console console = new Console(ConsoleConfig.defaults().withGameControllerPort(0)
                .withUdp(UdpConfig.defaults().withBindAddress("127.0.0.1").withListenPort(0))).start()) {
            try (ReplayViewModel model = new ReplayViewModel(console.replays(), console.teamSchemas())) {
                assertTrue(model.current().isEmpty());
                model.open(sample);
                assertEquals(new ReplayViewModel.Message("Opening demo-team.mcap …", false), model.message());
                Await.until("the typed recording is open, and said so", () -> {
                    model.refresh();
                    return model.hasReplay() && model.message().text().equals("Opened demo-team.mcap.");
                });
                assertEquals(List.of(), model.alignedFiles(), "one file: nothing aligned");
                model.closeReplay();
                Await.until("the replay closed, and its message with it", () -> model.refresh() == ReplayViewModel.Pulled.NEW_REPLAY);
                assertTrue(model.current().isEmpty());
                assertEquals(new ReplayViewModel.Message("", false), model.message());
                assertEquals("No recording open.", model.positionLine());

                model.open(" ");
                assertEquals(new ReplayViewModel.Message("Type or choose a recording to open.", true), model.message());
            }
        }
    }

    @Test
    void loopBNeedsAAndADifferentTimeAndLoopsEitherWay() {
        LoopMarks model = new LoopMarks();
        assertEquals("Set A first", model.markB(at(5_000_000, true, -1, -1)).refusal());
        assertEquals("A at 0:09.0, now set B", model.markA(at(10_000_000, true, -1, -1)));
        assertEquals(Optional.empty(), model.loopLine(at(10_000_000, true, 2_000_000, 3_000_000)), "marking: no loop line");
        assertEquals("A and B are the same time", model.markB(at(10_000_000, true, -1, -1)).refusal());
        LoopMarks.LoopB b = model.markB(at(4_000_000, true, -1, -1));
        assertNull(b.refusal());
        assertEquals(4_000_000, b.fromMicros());
        assertEquals(10_000_000, b.toMicros());
        assertEquals("Set A first", model.markB(at(6_000_000, true, -1, -1)).refusal(), "a loop set forgets A");
        assertEquals(Optional.of("Loop 0:03.0–0:09.0"), model.loopLine(at(6_000_000, true, 4_000_000, 10_000_000)));
        model.markA(at(7_000_000, true, -1, -1));
        model.clear();
        assertEquals("Set A first", model.markB(at(8_000_000, true, -1, -1)).refusal());
    }

    @Test
    void thePositionLineSaysHowTheReplayPlays() {
        assertEquals("No recording open.", ReplayViewModel.position(null, 0, false));
        String playing = ReplayViewModel.position(at(11_000_000, true, -1, -1), 7, false);
        assertTrue(playing.contains("playing at 2.5×"), playing);
        assertTrue(playing.contains("12,345 envelopes"), playing);
        assertTrue(playing.endsWith("7 events"), playing);
        assertTrue(ReplayViewModel.position(at(11_000_000, false, -1, -1), 0, true).endsWith("paused  ·  12,345 envelopes  ·  reading events…"));
        assertEquals("No goal after this point.", ReplayViewModel.noneAfter(TimelineEvent.Type.GOAL));
    }
}
