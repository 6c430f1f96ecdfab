package touchline.ui.frame;

/**
 * Which robot's option a visualisation shows. A layout keeps it, so a view restored before
 * its robot is back simply waits for the robot.
 */
public record ViewSource(int robotId, String option) {

    public static final ViewSource NONE = new ViewSource(-1, "");

    public boolean isSet() {
        return robotId >= 0 && !option.isEmpty();
    }

    /** Text form for layout files: {@code 3/demo.plotter}. */
    public String encode() {
        return robotId + "/" + option;
    }

    public static ViewSource decode(String s) {
        if (s == null || s.isEmpty()) {
            return NONE;
        }
        int slash = s.indexOf('/');
        try {
            return slash < 0 ? NONE : new ViewSource(Integer.parseInt(s.substring(0, slash)), s.substring(slash + 1));
        } catch (NumberFormatException e) {
            return NONE;
        }
    }

    @Override
    public String toString() {
        return isSet() ? "robot " + robotId + " · " + option : "(no source)";
    }
}
