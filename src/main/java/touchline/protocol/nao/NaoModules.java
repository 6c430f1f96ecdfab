package touchline.protocol.nao;

import java.util.List;

/**
 * The modules a NAO's robot side answers, by name: the standard NAOqi modules Touchline calls,
 * and Touchline's own {@value #ROBOT_SIDE} module (the robot side about itself: its modules, call
 * log and counters), which a NAO without Touchline's robot side does not have. The one list the
 * window's NAO view offers and {@code touchline nao methods} walks.
 */
public final class NaoModules {

    /** The standard NAOqi modules. */
    public static final List<String> NAOQI = List.of("ALMotion", "ALRobotPosture", "ALTextToSpeech", "ALMemory",
            "ALBattery", "ALVideoDevice");

    /** Touchline's robot-side module; not NAOqi's. */
    public static final String ROBOT_SIDE = "Robot";

    /** Every module Touchline's robot side answers: {@link #NAOQI} and {@link #ROBOT_SIDE}. */
    public static final List<String> ALL = java.util.stream.Stream.concat(NAOQI.stream(), java.util.stream.Stream.of(ROBOT_SIDE))
            .toList();

    private NaoModules() {
    }
}
