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
        long[] nowMicros = {1_500_000};
        StartMarks marks = new StartMarks(out, 1_000, () -> nowMicros[0]); // the JVM started at 1 000 ms
        nowMicros[0] = 1_750_000;
        marks.cameOnline(3, true);
        marks.windowShown();
        marks.cameOnline(4, true);
        marks.wentOffline(3);
        marks.cameOnline(3, false);
        marks.windowShown();
        String[] lines = bytes.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(2, lines.length, String.join("|", lines));
        assertEquals(StartMarks.DATA_MARK + " (robot 3) 750 ms after the JVM started", lines[0]);
        assertEquals(StartMarks.WINDOW_MARK + " 750 ms after the JVM started", lines[1]);
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
