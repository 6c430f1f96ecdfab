/**
 * The GameController's wire formats, one class per format version: game states ({@code HlGameState12}, {@code
 * HslGameState20}, {@code HslGameState19}, {@code SplGameState18}, {@code GameState8}, {@code GameState7}) in the
 * format-neutral {@code GameControlData} / {@code TeamInfo} / {@code RobotInfo}, recognised by {@code
 * KnownGameStateFormats}; return packets ({@code ReturnPacket}, {@code ReturnPacketDecoder}, {@code
 * ForwardedReturnPacket}) and the HSL monitor request ({@code MonitorRequest}). A rejected datagram is a {@code
 * Decoded} value with its {@code DecodeFailure}, never an exception. The state names and which states are play
 * have one owner: {@code GameControlData.stateName}, {@code stateCode}, {@code isPlay}.
 * <p>
 * May depend on: nothing of Touchline's (the protocol layer); pure.
 */
package touchline.protocol.gamecontroller;
