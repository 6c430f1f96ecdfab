/**
 * The reliable stream that shares a robot's UDP port (an alternating-bit derivative, {@code ReliableStream}), as a
 * pure state machine fed segments, sends and polls, and the thesis' acceptance test on it ({@code Mathe}).
 * <p>
 * May depend on: the protocol layer only; pure.
 */
package touchline.protocol.reliable;
