package touchline.cli;

import org.junit.jupiter.api.Test;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class StartMarksTest {

    @Test
    void eachStartMarkIsWrittenOnceWithTheTimeSinceTheJvmStarted() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        // a JVM started at 0 ms since the epoch: the marks' figures are the current time, above zero
        StartMarks marks = new StartMarks(out, 0);
        marks.cameOnline(3, true);
        marks.windowShown();
        marks.cameOnline(4, true);
        marks.wentOffline(3);
        marks.cameOnline(3, false);
        marks.windowShown();
        String[] lines = bytes.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(2, lines.length, String.join("|", lines));
        assertTrue(lines[0].startsWith(StartMarks.DATA_MARK + " (robot 3) "), lines[0]);
        assertTrue(lines[1].startsWith(StartMarks.WINDOW_MARK + " "), lines[1]);
        assertTrue(lines[1].endsWith(" ms after the JVM started"), lines[1]);
    }

    @Test
    void onlyATrainingRunClosesItsWindowByItself() {
        String before = System.getProperty(StartMarks.TRAINING_PROPERTY);
        try {
            System.clearProperty(StartMarks.TRAINING_PROPERTY);
            assertEquals(0, StartMarks.trainingFrames());
            System.setProperty(StartMarks.TRAINING_PROPERTY, "120");
            assertEquals(120, StartMarks.trainingFrames());
        } finally {
            if (before == null) {
                System.clearProperty(StartMarks.TRAINING_PROPERTY);
            } else {
                System.setProperty(StartMarks.TRAINING_PROPERTY, before);
            }
        }
    }
}
