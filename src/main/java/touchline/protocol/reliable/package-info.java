/**
 * The reliable stream that shares a robot's UDP port (an alternating-bit derivative, {@code ReliableStream}), as a
 * pure state machine fed segments, sends and polls (the thesis' acceptance test on it, {@code Mathe}, is a test fixture).
 * <p>
 * May depend on: the protocol layer only; pure.
 */
package touchline.protocol.reliable;
