package touchline.transport;

/** The wire protocol that carried an {@link Envelope}. */
public enum Channel {
    /** FUmanoids protobuf {@code Message} over UDP (legacy 12-byte or 4-byte length header). */
    FUMANOID,
    /** Reliable-stream segment (sequence byte + ack byte) sharing the robot's UDP port. */
    RELIABLE_STREAM,
    /** GameController game-state ("RGme") or return ("RGrt") packet. */
    GAMECONTROLLER,
    /** NAO RPC request or reply over ZeroMQ. */
    NAO_RPC,
    /** NAO camera request or JPEG frame over ZeroMQ. */
    NAO_CAMERA,
    /** Connection events of a link (NAO online/lost, ...); raw holds the UTF-8 text. */
    LINK_EVENT,
    /** Team messages between a team's robots (UDP 10000 + team number), heard for the budget guard. */
    TEAM_MESSAGE,
    /**
     * A message on a channel another tool wrote into a recording (replay only, never live):
     * kind = the MCAP topic, raw = the message's bytes, message = the decoded protobuf message
     * (by the schema in the file), ros = the decoded ROS 2 (CDR) or JSON message.
     */
    FOREIGN,
    /**
     * A message from a robot's Foxglove WebSocket server (a ROS 2 robot's {@code foxglove_bridge}):
     * kind = the topic, raw = the payload as the server sent it, message = the payload decoded
     * (ROS 2 CDR, JSON or protobuf, as a protobuf message), or null with {@code error} when it
     * did not decode.
     */
    BRIDGE
}
