/**
 * The GameController's runtime in the console: the embedded GameController ({@code EmbeddedGameController}),
 * listening to 3838 when another one referees ({@code GameStateWatch}, {@code RivalGameControllers}), which
 * GameController the console believes ({@code GameControllerSources}) and match mode, the rule that during play
 * only the GameController talks to the robots ({@code MatchMode}).
 * <p>
 * May depend on: as app: game, transport, model, record, security, protocol.
 */
package touchline.app.game;
