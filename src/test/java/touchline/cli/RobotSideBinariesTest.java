package touchline.cli;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The one lookup of the robot-side programs: where, whether built, and the sentence when not. */
class RobotSideBinariesTest {

    @Test
    void aBuiltProgramIsFoundAndNothingIsSaid(@TempDir Path dir) throws Exception {
        Path robot = Files.createFile(dir.resolve("touchline-robot"));
        assertTrue(robot.toFile().setExecutable(true));
        RobotSideBinaries binaries = new RobotSideBinaries(dir);
        assertEquals(robot, binaries.of("touchline-robot"));
        assertTrue(binaries.isBuilt("touchline-robot"));
        assertEquals(Optional.empty(), binaries.missing("touchline-robot"));
    }

    @Test
    void aMissingOrNonExecutableProgramIsSaidWithWhereAndHowToBuildIt(@TempDir Path dir) throws Exception {
        Path plain = Files.createFile(dir.resolve("touchline-nao-sim"));
        assertTrue(plain.toFile().setExecutable(false));
        RobotSideBinaries binaries = new RobotSideBinaries(dir);
        assertFalse(binaries.isBuilt("touchline-nao-sim"));
        assertEquals("The robot-side programs are not built (" + dir.resolve("touchline-robot") + " is missing): run "
                + "./touchline build, or point -Dtouchline.robotside.bin at the directory that holds them.",
                binaries.missing("touchline-robot").orElseThrow());
        assertTrue(binaries.missing("touchline-nao-sim").orElseThrow().contains(plain.toString()));
    }

    @Test
    void withoutThePropertyTheBuildDirectoryUnderTheWorkingDirectory() {
        String before = System.getProperty(RobotSideBinaries.PROPERTY);
        try {
            System.clearProperty(RobotSideBinaries.PROPERTY);
            assertEquals(Path.of("robot-side/build/bin"), new RobotSideBinaries().dir());
            System.setProperty(RobotSideBinaries.PROPERTY, "/opt/touchline/bin");
            assertEquals(Path.of("/opt/touchline/bin", "touchline-robot"), new RobotSideBinaries().of("touchline-robot"));
        } finally {
            if (before == null) {
                System.clearProperty(RobotSideBinaries.PROPERTY);
            } else {
                System.setProperty(RobotSideBinaries.PROPERTY, before);
            }
        }
    }
}
