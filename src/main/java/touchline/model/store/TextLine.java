package touchline.model.store;

/**
 * One line of debug text from a robot: when the console received it, the robot's own time
 * stamp (0 when it sent none), which robot and option it came from.
 */
public record TextLine(long timeMicros, long robotTimestamp, int robotId, String option, String text) { }
