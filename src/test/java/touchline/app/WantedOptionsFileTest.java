package touchline.app;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.*;

class WantedOptionsFileTest {

    @Test
    void keepsTheWantedOptionsPerRobotBetweenRuns(@TempDir Path dir) {
        Path file = dir.resolve("sub").resolve("wanted-options.properties");
        new WantedOptionsFile(file).write(Map.of(7, Set.of("demo.text", "team.a=b c"), 2, Set.of("havimo.grid")));
        assertEquals(Map.of(7, Set.of("demo.text", "team.a=b c"), 2, Set.of("havimo.grid")),
                new WantedOptionsFile(file).read());
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
        f.write(Map.of(1, Set.of("x")));
        assertTrue(f.problem().startsWith("could not remember"), f.problem());
    }
}
