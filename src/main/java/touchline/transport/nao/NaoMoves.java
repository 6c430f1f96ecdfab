package touchline.transport.nao;

import java.util.List;
import java.util.concurrent.CompletableFuture;

/**
 * The high-level NAO commands the console offers, each a sequence of NAOqi calls through a
 * {@link NaoLink} that stops at the first failure: stand, sit (the safe position), turn the
 * head, walk at a velocity, say a text. Walking goes through {@code ALMotion.moveToward},
 * whose minimum interval in the link's configuration keeps keyboard repeat from flooding
 * the robot while the latest velocity (including "stop") always arrives.
 */
public final class NaoMoves {

    private final NaoLink link;

    public NaoMoves(NaoLink link) {
        this.link = link;
    }

    public static List<NaoCall> standSequence() {
        return List.of(NaoCall.of("ALRobotPosture", "goToPosture", "Stand", 1.0f),
                NaoCall.of("ALMotion", "moveInit"));
    }

    public static List<NaoCall> sitSequence() {
        return List.of(NaoCall.of("ALMotion", "stopMove"),
                NaoCall.of("ALRobotPosture", "goToPosture", "Sit", 1.0f));
    }

    /** Head yaw in radians (positive = left), clamped to the joint's range. */
    public static List<NaoCall> turnHeadSequence(double yawRadians) {
        float yaw = (float) Math.max(-2.0857, Math.min(2.0857, yawRadians));
        return List.of(NaoCall.of("ALMotion", "setStiffnesses", "HeadYaw", 1.0f),
                NaoCall.of("ALMotion", "setAngles", "HeadYaw", yaw, 0.5f),
                NaoCall.of("ALMotion", "setStiffnesses", "HeadYaw", 0.0f));
    }

    public CompletableFuture<SequenceOutcome> stand() {
        return link.sequence(standSequence());
    }

    public CompletableFuture<SequenceOutcome> sit() {
        return link.sequence(sitSequence());
    }

    public CompletableFuture<SequenceOutcome> turnHead(double yawRadians) {
        return link.sequence(turnHeadSequence(yawRadians));
    }

    /** Sends the walk velocity (normalised, see {@link WalkInput}); {@link WalkInput#STOP} stops. */
    public CompletableFuture<CallOutcome> walk(WalkInput input) {
        return link.call(NaoCall.of("ALMotion", "moveToward", input.x(), input.y(), input.theta()));
    }

    public CompletableFuture<CallOutcome> say(String text) {
        return link.call(NaoCall.of("ALTextToSpeech", "say", text));
    }
}
