/**
 * The application core both faces share, as use-case services: {@code Console}, the composition root that builds
 * them from a {@code ConsoleConfig}, starts them and closes them in reverse order; {@code LiveField} (the robots'
 * port, the Envelope stream and its read models), {@code Referee} (match mode, the GameControllers heard, the
 * embedded one), {@code OptionSwitches}, {@code Recordings}, {@code Replays} (a {@code Replay} into the stream),
 * {@code Naos} (a {@code NaoSession}, {@code NaoCamera}, {@code NaoViewModel} and the feeds), {@code TeamBudget},
 * {@code RemoteView}, {@code LiveServing} (the live server) and {@code TeamSchemas} (the team's own message
 * types); the gate every command passes ({@code FieldGate}); the one wall clock ({@code SystemClock}); and what the
 * faces show about the run ({@code RuntimeReport}, {@code ProductVersion}). A face takes the services it needs,
 * never the {@code Console}. In {@code app.bridges}: the team's ROS 2 robots behind their Foxglove bridges, a
 * service like the others ({@code RosBridges}, named by {@code BridgeAddress} and a {@code TeamFile};
 * {@code ServerKind} tells a lone {@code --connect URL} of another Touchline from a bridge).
 * <p>
 * May depend on: serve, game, transport, model, record, security and protocol. Only the faces (ui, cli) use it.
 */
package touchline.app;
