package touchline.transport;

import touchline.proto.Fumanoid;

/** The outbound path to robots as the model sees it: send one message to one robot. */
@FunctionalInterface
public interface RobotCommands {
    SendResult send(int robotId, Fumanoid.Message message);
}
