package touchline.model;

import java.util.List;

/**
 * A robot's debug options: the list it sent (empty until one arrived), how often the console
 * asked for it, and why the last command did not go out, if it did not.
 */
public record RobotOptions(int robotId, boolean listReceived, int listRequests, List<OptionState> options,
                           String lastHoldReason) {

    public java.util.Optional<OptionState> option(String name) {
        return options.stream().filter(o -> o.name().equals(name)).findFirst();
    }
}
