package touchline.fuzz;

import java.util.List;
import java.util.Optional;

/** Every decoder of outside input in the console, by name. */
final class Targets {

    private final List<FuzzTarget> all = List.of(new FramingTarget(), new MessageTarget(), new GameStateTarget(),
            new ReturnPacketTarget(), new ReliableStreamTarget(), new MixedValueTarget(), new JpegHeaderTarget(),
            new ParamSyntaxTarget(), new TrailerTarget(), new RecordingTarget(), new ServeClientTarget(),
            new GcMonitorTarget(), new Ros2DefinitionTarget(), new Ros2CdrTarget());

    List<FuzzTarget> all() {
        return all;
    }

    Optional<FuzzTarget> named(String name) {
        return all.stream().filter(t -> t.name().equals(name)).findFirst();
    }
}
