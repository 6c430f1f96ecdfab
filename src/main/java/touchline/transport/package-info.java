/**
 * Sockets into a stream of typed, time-stamped {@code Envelope}s and commands into datagrams: the console's UDP
 * endpoint ({@code UdpTransport} on {@code UdpBackend}, its pipeline {@code DatagramIntake} → {@code DecodeStage}
 * / {@code FumanoidDecoder}, threads kept apart by {@code CoreSplit}), where robots are ({@code PeerTable}), the
 * the two streams ({@code LiveStream}, and {@code ReplayStream}, which no sender can be handed; both fan out
 * through an {@code EnvelopeBus} to {@code EnvelopeSink}s), the reliable stream per peer ({@code ReliableSession}),
 * what may be sent now ({@code SendGate} and its {@code Hold}, {@code SendResult}) and the counts and clocks every layer above shares
 * ({@code TrafficCounters}, {@code MicrosClock}, {@code MonotonicClock}).
 * <p>
 * One owner per fact: a host and port typed by a user is a {@code HostPort} (never a name lookup while parsing), a
 * recording's peer text a {@code PeerText}; the game state an envelope carries is read by {@code GameStateReader}
 * over {@code KnownGameStateFormats}. The two ingest threads run on different cores ({@code CoreSplit}, Linux, two
 * or more CPUs; {@code -Dtouchline.udp.cores=shared} leaves them free); a thread inherits its starter's CPUs, so
 * nothing starts a thread from either: executors the publishers feed start theirs when made.
 * <p>
 * May depend on: protocol and security (it tags and checks datagrams).
 */
package touchline.transport;
