/**
 * The GameController on the network: the embedded GameController's sender on a drift-free 500 ms grid ({@code
 * GcSender}, {@code SendSchedule}, {@code RealtimePriority}), a socket with its own thread for 3838 and the return
 * port ({@code GcListener}), the HSL monitor protocol both ways ({@code MonitorService}, {@code GcMonitor}),
 * robots' liveness from their return packets ({@code RobotLiveness}), malformed datagrams counted ({@code
 * BadPackets}) and the settings ({@code GcConfig}, {@code GcProfile}).
 * <p>
 * May depend on: protocol and security, and the transport layer's own types.
 */
package touchline.transport.gamecontroller;
