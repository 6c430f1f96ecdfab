/**
 * Bytes and messages, nothing else: the FUmanoids datagram headers ({@code Framing}, {@code FrameCodec}, {@code
 * DatagramClass}), decoding a payload into a protobuf {@code Message} with the extension registry ({@code
 * MessageCodec}, {@code MessageKinds}, {@code MessageResult}), the debug data a message carries ({@code
 * DebugData}) and its text for the consoles and the CLI ({@code MessageText}, {@code Hex}). Every codec is a pure
 * function with golden byte vectors in its tests.
 * <p>
 * May depend on: nothing of Touchline's but the generated {@code touchline.proto} classes; no threads, files or
 * sockets (ArchitectureTest).
 */
package touchline.protocol;
