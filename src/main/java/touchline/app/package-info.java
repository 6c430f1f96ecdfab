/**
 * The application core both faces share: {@code Console}, the composition root that builds the transports, the
 * model, the recorder and replays and closes them, from a {@code ConsoleConfig}; a replay into the stream ({@code
 * Replay}); a NAO driven through the core ({@code NaoSession}, {@code NaoCamera}, {@code NaoViewModel} and its
 * feeds); the team's own message types ({@code TeamSchemas}); the one wall clock ({@code SystemClock}); and what
 * the faces show about the run ({@code RuntimeReport}, {@code ProductVersion}). In {@code app.bridges}: the team's
 * ROS 2 robots behind their Foxglove bridges ({@code RosBridges}, named by {@code BridgeAddress} and a
 * {@code TeamFile}; {@code ServerKind} tells a lone {@code --connect URL} of another Touchline from a bridge).
 * <p>
 * May depend on: game, transport, model, record, security and protocol. Only the faces (ui, cli) use it.
 */
package touchline.app;
