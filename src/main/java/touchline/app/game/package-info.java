/**
 * The GameController's runtime in the console: the embedded GameController ({@code EmbeddedGameController})
 * whose game has one owner thread ({@code GameRuntime}, publishing {@code RefereeSnapshot}s), the one listener
 * on 3838 ({@code GameStateWatch}) feeding the one source of GameController states for match mode
 * ({@code GameControllerStates}), which GameController the console believes ({@code GameControllerSources}),
 * the one table of other GameControllers ({@code RivalGameControllers}) and match mode, the rule that during
 * play only the GameController talks to the robots ({@code MatchMode}). Match mode has three labelled inputs:
 * GameController states, the robots' reported state ({@code app.ReportedGameState}) and a remote console's
 * GameController ({@code app.RemoteGameState}). Other GameControllers (intruders while listening, rivals while
 * refereeing) are one table with one window, match mode's {@code STALE_MS} (5 s): a warning lasts exactly as long
 * as the claim it warns of still acts on match mode (ten missed 500 ms packets).
 * <p>
 * May depend on: as app: game, transport, model, record, security, protocol.
 */
package touchline.app.game;
