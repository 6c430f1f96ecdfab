package touchline.app;

import touchline.model.DebugOptionSession;
import touchline.model.OptionState;
import touchline.transport.SendResult;
import touchline.transport.remote.RemoteStream;

import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;

/**
 * Switching the robots' debug options: what this console's user wants on (remembered in a file
 * beside the layouts when asked), what a tool asks for ({@code options}, here or through the
 * live server), and, viewing a remote Touchline, asking that one. Every switch passes match mode.
 */
public final class OptionSwitches {

    private final DebugOptionSession options;
    private final RemoteView remote;
    private volatile WantedOptionsFile wantedFile;

    OptionSwitches(DebugOptionSession options, RemoteView remote) {
        this.options = options;
        this.remote = remote;
    }

    /** The robots' option lists and what is wanted of them. */
    public DebugOptionSession options() {
        return options;
    }

    public SendResult set(int robotId, String option, boolean on) {
        if (remote.viewing()) {
            return SendResult.failed(RemoteView.COMMANDS_OFF);
        }
        return remembered(options.setWanted(robotId, option, on));
    }

    /**
     * Switches an option off that the user names, even one another console switched on (the
     * {@code options --off} command); {@link #set} only switches off what this console's user
     * switched on.
     */
    public SendResult switchOff(int robotId, String option) {
        if (remote.viewing()) {
            return SendResult.failed(RemoteView.COMMANDS_OFF);
        }
        return remembered(options.switchOff(robotId, option));
    }

    private SendResult remembered(SendResult result) {
        WantedOptionsFile f = wantedFile;
        if (f != null) {
            f.write(options.allWanted(), options.allMatchItems());
        }
        return result;
    }

    /** Every tick: the match items chosen in the options view or by a command are kept with the wanted options. */
    void keepMatch() {
        WantedOptionsFile f = wantedFile;
        if (f != null) {
            f.keepMatch(options.allWanted(), options.allMatchItems());
        }
    }

    /**
     * A switch a tool asked for (the {@code options} command, here or through this console's live
     * server): on is wanted by this console from now on, off switches the option off whoever
     * switched it on; both pass match mode.
     */
    public SendResult switchAsAsked(int robotId, String option, boolean on) {
        return on ? set(robotId, option, true) : switchOff(robotId, option);
    }

    /**
     * Whether an option shows as on (its box in the options view, [x] in {@code options}): wanted
     * by this console; viewing a remote Touchline, on on the robot as the serving console hears it.
     */
    public boolean shownOn(OptionState option) {
        return remote.viewing() ? option.enabledOnRobot() : option.wanted();
    }

    /**
     * Asks the remote Touchline this console views to switch an option ({@link #switchAsAsked}
     * there, through its match mode); completes with its answer. Not viewing one: "not sent" at once.
     */
    public CompletableFuture<SendResult> switchRemotely(int robotId, String option, boolean on) {
        RemoteStream r = remote.stream().orElse(null);
        return r == null ? CompletableFuture.completedFuture(SendResult.failed("not viewing a remote Touchline"))
                : r.switchOption(robotId, option, on);
    }

    /**
     * Keeps the wanted debug options in {@code file} (beside the layouts): what it holds from an
     * earlier run is wanted again now, each robot getting its options when it appears, and every
     * switch from now on is written there. A file that cannot be read or written only costs the
     * remembering ({@link #wantedProblem()}). Viewing a remote Touchline, nothing: the options are
     * the serving console's, and this one wants none of its own.
     */
    public void rememberWanted(Path file) {
        if (remote.viewing()) {
            return;
        }
        WantedOptionsFile f = new WantedOptionsFile(file);
        options.restoreWanted(f.read());
        options.restoreMatchItems(f.readMatch());
        wantedFile = f;
    }

    /** Why the wanted options could not be read or kept, or empty. */
    public String wantedProblem() {
        WantedOptionsFile f = wantedFile;
        return f == null ? "" : f.problem();
    }
}
