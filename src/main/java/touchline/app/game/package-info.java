/**
 * The GameController's runtime in the console: the embedded GameController ({@code EmbeddedGameController})
 * whose game has one owner thread ({@code GameRuntime}, publishing {@code RefereeSnapshot}s), the one listener
 * on 3838 ({@code GameStateWatch}) feeding the one source of GameController states for match mode
 * ({@code GameControllerStates}), which GameController the console believes ({@code GameControllerSources}),
 * the one table of other GameControllers ({@code RivalGameControllers}) and match mode, the rule that during
 * play only the GameController talks to the robots ({@code MatchMode}).
 * <p>
 * May depend on: as app: game, transport, model, record, security, protocol.
 */
package touchline.app.game;
