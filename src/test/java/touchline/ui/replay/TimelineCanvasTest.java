package touchline.ui.replay;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The timeline's time/pixel mapping and the texts the view shows. */
class TimelineCanvasTest {

    @Test
    void timeAndPixelMapBothWaysAndClampToTheRecording() {
        long start = 1_000_000_000L;
        long end = start + 180_000_000L;
        double width = 600;
        assertEquals(TimelineCanvas.PAD, TimelineCanvas.xAt(start, start, end, width));
        assertEquals(width - TimelineCanvas.PAD, TimelineCanvas.xAt(end, start, end, width));
        assertEquals(start, TimelineCanvas.timeAt(0, start, end, width));
        assertEquals(end, TimelineCanvas.timeAt(width + 50, start, end, width));
        long goal = start + 120_000_000L;
        long back = TimelineCanvas.timeAt(TimelineCanvas.xAt(goal, start, end, width), start, end, width);
        assertEquals(goal, back, 1000);
        assertEquals(TimelineCanvas.PAD, TimelineCanvas.xAt(start, start, start, width), "an empty recording");
    }

    @Test
    void textsForTimesAndSpeeds() {
        assertEquals("0:00.0", TimelineCanvas.clock(0));
        assertEquals("2:00.5", TimelineCanvas.clock(120_500_000L));
        assertEquals("1:00:01", TimelineCanvas.clock(3_601_000_000L));
        assertEquals("50×", ReplayViewModel.speedText(50));
        assertEquals("0.1×", ReplayViewModel.speedText(0.1));
        assertEquals("0.25×", ReplayViewModel.speedText(0.25));
        assertEquals("2.5 MiB", RecordPanel.bytes(2_621_440));
    }
}
