package touchline.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * The one lookup of the robot-side build's programs ({@code touchline-robot},
 * {@code touchline-nao-sim}, {@code touchline-blast}, ...): in {@code -Dtouchline.robotside.bin}
 * (the launcher sets it), else {@code robot-side/build/bin} under the working directory. The
 * demo, the screenshots, the benchmarks and the tests all find them here, and all say the same
 * sentence when one is missing.
 */
public final class RobotSideBinaries {

    /** The system property naming the directory. */
    public static final String PROPERTY = "touchline.robotside.bin";
    static final String DEFAULT_DIR = "robot-side/build/bin";

    private final Path dir;

    /** Where the property, or else the default, says the programs are. */
    public RobotSideBinaries() {
        this(Path.of(System.getProperty(PROPERTY, DEFAULT_DIR)));
    }

    public RobotSideBinaries(Path dir) {
        this.dir = dir;
    }

    public Path dir() {
        return dir;
    }

    /** Where {@code program} is (whether built or not). */
    public Path of(String program) {
        return dir.resolve(program);
    }

    public boolean isBuilt(String program) {
        return Files.isExecutable(of(program));
    }

    /** Empty when {@code program} is built; else one sentence: what is missing where, and how to build it. */
    public Optional<String> missing(String program) {
        if (isBuilt(program)) {
            return Optional.empty();
        }
        return Optional.of("The robot-side programs are not built (" + of(program) + " is missing): run "
                + "./touchline build, or point -D" + PROPERTY + " at the directory that holds them.");
    }
}
