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

    /**
     * A port this command binds is taken: the sentence names the port, what it is for and the
     * flag that moves it, e.g. "UDP port 11011 (robots) on 0.0.0.0 is already in use (…): close
     * that program, or start with --port N (a free port), e.g. --port 11012."
     */
    static StartFailure portInUse(String protocol, int port, String purpose, String bind, String flag) {
        return new StartFailure(protocol + " port " + port + " (" + purpose + ") on " + bind + " is already in use "
                + "(another Touchline or a team tool is listening there): close that program, or start with " + flag
                + " N (a free port), e.g. " + flag + " " + (port == 65535 ? port - 1 : port + 1) + ".", PORT_IN_USE);
    }

    /** The UDP port the robots send to ({@code --port} of console, listen, record, options, stream). */
    static StartFailure robotsPortInUse(String bind, int port) {
        return portInUse("UDP", port, "robots", bind, "--port");
    }

    /** A file or option the user gave that cannot be used; {@code sentence} says which and why. */
    static StartFailure badInput(String sentence) {
        return new StartFailure(sentence, BAD_INPUT);
    }

    static StartFailure teamPortInUse(String bind, int port) {
        return new StartFailure("UDP port " + port + " (team messages) on " + bind + " is already in use by a "
                + "program that does not share it: close it, or start with --team-port N (the port the team's "
                + "robots send to).", PORT_IN_USE);
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
