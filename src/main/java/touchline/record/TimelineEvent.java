package touchline.record;

/**
 * Something worth jumping to in a recording: a goal, a game state change, a player penalised, a robot lost.
 *
 * @param timeMicros when it happened, microseconds since the epoch (the envelopes' clock)
 * @param type       what kind of event
 * @param robotId    the robot concerned, or -1 for team/game events
 * @param label      a short text for the timeline, e.g. "GC: READY → SET"
 */
public record TimelineEvent(long timeMicros, Type type, int robotId, String label) {

    /** Event categories the timeline shows and seeks by. */
    public enum Type { GOAL, STATE_CHANGE, PENALTY, ROBOT_LOST }
}
