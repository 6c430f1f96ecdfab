package touchline.cli;

import java.net.BindException;

/**
 * Why a command could not start, in one sentence that says what to do, with the exit code the
 * shell sees. Main prints the sentence alone (no stack trace): at a tournament the reader is a
 * team member, not the developer.
 */
final class StartFailure extends Exception {

    static final int PORT_IN_USE = 3;
    static final int NO_DISPLAY = 4;
    static final int ROBOT_SIDE_MISSING = 5;
    static final int BAD_INPUT = 2;

    private final int exitCode;

    StartFailure(String sentence, int exitCode) {
        super(sentence, null, false, false);
        this.exitCode = exitCode;
    }

    int exitCode() {
        return exitCode;
    }

    static StartFailure portInUse(String bind, int port) {
        return new StartFailure("UDP port " + port + " on " + bind + " is already in use (another Touchline or a team "
                + "tool is listening there): close that program, or start with --port and a free port, e.g. --port "
                + (port == 65535 ? 11012 : port + 1) + ".", PORT_IN_USE);
    }

    /** A file or option the user gave that cannot be used; {@code sentence} says which and why. */
    static StartFailure badInput(String sentence) {
        return new StartFailure(sentence, BAD_INPUT);
    }

    static StartFailure teamPortInUse(String bind, int port) {
        return new StartFailure("UDP port " + port + " on " + bind + " (the team's messages) is already in use by a "
                + "program that does not share it: close it, or give the port with --team-port.", PORT_IN_USE);
    }

    static StartFailure noDisplay(String why) {
        return new StartFailure("The console window needs a display, and " + why + ": start it on the desktop, over "
                + "ssh -X, or use the headless commands (touchline listen, touchline record).", NO_DISPLAY);
    }

    /** {@code sentence} from {@link RobotSideBinaries#missing}. */
    static StartFailure robotSideMissing(String sentence) {
        return new StartFailure(sentence, ROBOT_SIDE_MISSING);
    }

    /** True when {@code t} or one of its causes says the address is taken (Netty's native bind says it in words). */
    static boolean addressInUse(Throwable t) {
        for (Throwable c = t; c != null; c = c.getCause()) {
            if (c instanceof BindException || (c.getMessage() != null && c.getMessage().contains("Address already in use"))) {
                return true;
            }
        }
        return false;
    }
}
