package touchline.record;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

/** The notes' sentences, and the notes of several files played on one timeline. */
class ReplayNotesTest {

    private static ReplayNotes odom(boolean complete) {
        return new ReplayNotes(List.of("the recording is unfinished"),
                List.of(new ReplayNotes.SkippedChannel("/odom", "ros2msg/cdr", "encoding not supported", 1200)),
                List.of(new McapReader.Attachment("map.png", "image/png", 2048, 0)),
                Map.of("match", Map.of("field", "B"), McapWriter.FORMAT_METADATA, Map.of("version", "1")), complete);
    }

    @Test
    void theSentencesSayWhatWasSkippedWithCountsAndWhatTheFileHolds() {
        ReplayNotes n = odom(true);
        assertEquals(List.of("the recording is unfinished",
                "skipped 1,200 messages of 1 channel: /odom (ros2msg/cdr: encoding not supported) 1,200"), n.lines());
        assertEquals(List.of("attachment map.png (image/png, 2,048 bytes)", "metadata match: field=B"), n.contents());
        assertEquals("⚠ 1 problem with the file · 1,200 messages of 1 channel skipped", n.badge());
        assertEquals("", ReplayNotes.NONE.badge());
        assertEquals(List.of(), ReplayNotes.NONE.lines());
        assertEquals("skipped 1,200 messages so far of 1 channel: /odom (ros2msg/cdr: encoding not supported) 1,200",
                odom(false).skippedLine().orElseThrow());
    }

    @Test
    void notesOfSeveralFilesNameTheFileAndAddUp() {
        ReplayNotes both = odom(true).inFile("a.mcap").plus(odom(false).inFile("b.mcap"));
        assertFalse(both.complete());
        assertEquals(2400, both.skippedMessages());
        assertEquals(List.of("a.mcap: the recording is unfinished", "b.mcap: the recording is unfinished",
                "skipped 2,400 messages so far of 2 channels: a.mcap: /odom (ros2msg/cdr: encoding not supported)"
                        + " 1,200, b.mcap: /odom (ros2msg/cdr: encoding not supported) 1,200"), both.lines());
        assertEquals(List.of("attachment a.mcap: map.png (image/png, 2,048 bytes)",
                "attachment b.mcap: map.png (image/png, 2,048 bytes)", "metadata a.mcap: match: field=B",
                "metadata b.mcap: match: field=B"), both.contents());
    }
}
