package touchline.testing;

import org.junit.jupiter.api.Assumptions;
import touchline.cli.RobotSideBinaries;

import java.util.Optional;

import static org.junit.jupiter.api.Assertions.fail;

/**
 * A test's prerequisite from outside the JVM (the robot-side binaries, the Python interop
 * packages). On a developer's machine a missing one skips the test with the reason; under CI
 * ({@code CI=true}, as {@code .ci/run} is started) it fails the test with the same reason, so a
 * missing install step can never turn into a green run that tested nothing.
 */
public final class Requirement {

    private Requirement() {
    }

    /** True when the tests run under CI, where nothing may be skipped silently. */
    public static boolean underCi() {
        String ci = System.getenv("CI");
        return ci != null && !ci.isBlank() && !ci.equalsIgnoreCase("false") && !ci.equals("0");
    }

    /** Skips the test (or, under CI, fails it) with {@code reason} unless {@code present}. */
    public static void require(boolean present, String reason) {
        if (present) {
            return;
        }
        if (underCi()) {
            fail("missing under CI: " + reason);
        }
        Assumptions.assumeTrue(false, reason);
    }

    /** The robot-side program {@code name}, found by the product's own lookup ({@link RobotSideBinaries}). */
    public static void robotSide(String name) {
        Optional<String> missing = new RobotSideBinaries().missing(name);
        require(missing.isEmpty(), missing.orElse(""));
    }
}
