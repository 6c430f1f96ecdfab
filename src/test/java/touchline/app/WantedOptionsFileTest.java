package touchline.app;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

class WantedOptionsFileTest {

    @Test
    void keepsTheWantedOptionsPerRobotBetweenRuns(@TempDir Path dir) {
        Path file = dir.resolve("sub").resolve("wanted-options.properties");
        new WantedOptionsFile(file).write(Map.of(7, Set.of("demo.text", "team.a=b c"), 2, Set.of("havimo.grid")), Map.of());
        assertEquals(Map.of(7, Set.of("demo.text", "team.a=b c"), 2, Set.of("havimo.grid")),
                new WantedOptionsFile(file).read());
    }

    @Test
    void keepsEachRobotsMatchItemsInOrderBesideTheWantedOptions(@TempDir Path dir) {
        Path file = dir.resolve("wanted-options.properties");
        WantedOptionsFile f = new WantedOptionsFile(file);
        f.keepMatch(Map.of(7, Set.of("demo.text")), Map.of(7, List.of("demo.field", "demo.plotter"), 2, List.of()));
        WantedOptionsFile again = new WantedOptionsFile(file);
        assertEquals(Map.of(7, List.of("demo.field", "demo.plotter"), 2, List.of()), again.readMatch());
        assertEquals(Map.of(7, Set.of("demo.text")), again.read(), "the match items are not wanted options");
        assertEquals("", again.problem());
    }

    @Test
    void aMissingFileIsNothingWantedAndABadLineIsSkippedAndSaid(@TempDir Path dir) throws Exception {
        assertEquals(Map.of(), new WantedOptionsFile(dir.resolve("none")).read());
        Path file = dir.resolve("w.properties");
        Files.writeString(file, "seven/demo.text=on\n3/demo.text=on\n3/demo.plotter=off\nnoslash=on\n");
        WantedOptionsFile f = new WantedOptionsFile(file);
        assertEquals(Map.of(3, Set.of("demo.text")), f.read());
        assertTrue(f.problem().contains("seven/demo.text"), f.problem());
    }

    @Test
    void aFileThatCannotBeWrittenIsSaidNotThrown(@TempDir Path dir) throws Exception {
        Path blocker = dir.resolve("blocker");
        Files.writeString(blocker, "a file where a directory should be");
        WantedOptionsFile f = new WantedOptionsFile(blocker.resolve("wanted.properties"));
        f.write(Map.of(1, Set.of("x")), Map.of());
        assertTrue(f.problem().startsWith("could not remember"), f.problem());
    }
}
