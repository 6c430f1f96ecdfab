/**
 * Sockets into a stream of typed, time-stamped {@code Envelope}s and commands into datagrams: the console's UDP
 * endpoint ({@code UdpTransport} on {@code UdpBackend}, its pipeline {@code DatagramIntake} → {@code DecodeStage}
 * / {@code FumanoidDecoder}, threads kept apart by {@code CoreSplit}), where robots are ({@code PeerTable}), the
 * the two streams ({@code LiveStream}, and {@code ReplayStream}, which no sender can be handed; both fan out
 * through an {@code EnvelopeBus} to {@code EnvelopeSink}s), the reliable stream per peer ({@code ReliableSession}),
 * what may be sent now ({@code SendGate} and its {@code Hold}, {@code SendResult}) and the counts and clocks every layer above shares
 * ({@code TrafficCounters}, {@code MicrosClock}, {@code MonotonicClock}).
 * <p>
 * May depend on: protocol and security (it tags and checks datagrams).
 */
package touchline.transport;
