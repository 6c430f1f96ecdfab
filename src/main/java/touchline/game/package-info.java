/**
 * The referee's game as a library, pure. One engine for every league, {@code RefereeEngine}: a state changed
 * only by {@code LeagueAction}s (legality, undo, listeners), with what differs between leagues in a
 * {@code League} strategy ({@code HlLeague} here, {@code hsl.HslLeague}); {@code LeagueGame} is that engine with
 * a league, taking the league's own actions and those every league shares. The Humanoid League (and SPL) rules:
 * a refereed {@code Game} over a {@code GameState} (teams, players,
 * penalties, clocks) changed only by {@code Action}s ({@code ToReady}, {@code ToSet}, {@code ToPlaying}, {@code
 * Penalize}, {@code StartSetPlay}, ...) and by the {@code RefereeAction}s every league shares ({@code Goal},
 * {@code StartPenaltyShootout}),
 * which ask a league's state through {@code RefereeState}; each answers an {@code Outcome}; league parameters
 * ({@code LeagueParams}), the text form of actions for the CLI and scripts ({@code ActionSyntax}) and undo ({@code
 * UndoHistory}). Time comes in through {@code GameClock}; {@code RefereedGame} is what senders and receivers need
 * of any league's game.
 * <p>
 * <b>Actions both leagues have, rule by rule</b> (HL/SPL: this package; HSL 2026: {@code hsl}):
 * <table>
 * <caption>The same-named referee buttons of HL/SPL and HSL</caption>
 * <tr><th>button</th><th>the same</th><th>what differs</th><th>so</th></tr>
 * <tr><td>goal</td><td>legal in PLAYING for a team of the game, in a shoot-out only for the kicking
 * team; score +1; in a shoot-out the shot is marked in singleShots and over; else READY with the
 * other team's kick-off</td><td>HSL: no goal counts for a team marked for illegal communication; the
 * mercy rule (10 goals) ends the game, HL has none; READY starts a stoppage (a timeout gives
 * READY/SET back). A shot over is FINISHED, in HSL with the other team to shoot</td><td>one class,
 * {@code Goal} (a {@code RefereeAction}): the rule once, each difference a question to the league's
 * {@code RefereeState} ({@code countGoal}, {@code mercyGoals}, {@code shotScored}, {@code
 * readyForKickOff})</td></tr>
 * <tr><td>penalty shoot-out</td><td>legal when the second half (HSL: or extra time) ended level and
 * no shoot-out runs; INITIAL; shot counters 0</td><td>HL: the team that kicked off the game shoots
 * first and the players stay; HSL: the referee names the first team, every player becomes a
 * substitute until its team selects a shooter ({@code hsl.SelectShooter}), the shot clock is set</td>
 * <td>one class, {@code StartPenaltyShootout}: the first shooter a parameter ({@code GAME_KICK_OFF} or a
 * team), the shoot-out itself the league's {@code RefereeState.beginShootout}</td></tr>
 * <tr><td>penalise</td><td>a team's valid player without a penalty; never NONE or SUBSTITUTE</td>
 * <td>HL: the timer of a timed penalty starts with the call and ends it by itself ({@code
 * LeagueParams.penaltySeconds}). HSL: the operator starts the timer when the robot is outside,
 * durations grow with the team's earlier incremental penalties, motion in set only in SET, motion
 * in stop only while stopped, only pick-up in FINISHED, cautions (a second one sends off) and
 * send-offs on penalised players, what a release knows ({@code HslRules})</td><td>two classes,
 * {@code Penalize} and {@code hsl.HslPenalize}: two penalty sets ({@code Penalty}, the wire's {@code
 * HslPenalty}) and two timer models</td></tr>
 * <tr><td>unpenalise</td><td>a penalised robot comes back</td><td>HL: at once. HSL: the first press
 * starts the timer, a press after it ran out lets the robot in, {@code force} at once; sent-off and
 * substitutes stay out</td><td>two classes, {@code Unpenalize} and {@code hsl.HslUnpenalize}: the
 * HSL press is a two-step procedure HL does not have</td></tr>
 * <tr><td>timeout</td><td>a team timeout outside PLAYING while the team has one left</td><td>HL:
 * INITIAL with secondary TIMEOUT, from INITIAL, READY or SET with secondary state NORMAL; {@code ToReady} ends
 * it. HSL: a state of its own; also a referee timeout (also in play); penalty timers stop, time
 * since the last stoppage is given back, a timeout in a timeout adds to it, the other team kicks
 * off after it</td><td>two classes, {@code Timeout} and {@code hsl.HslTimeout}: different
 * procedures</td></tr>
 * <tr><td>set play</td><td>for a team of the game, from PLAYING (HSL's kick-off: from INITIAL or a
 * timeout)</td><td>HL: every set play
 * (penalty kick included) stays in PLAYING with the half clock stopped and the sub-modes READY,
 * PREPARE, EXECUTE ({@code SetPlayStep}). HSL: a kick-off (from INITIAL or a timeout) and a penalty
 * kick go to READY and SET; the others stop play, their 45 s count from "resume"</td><td>two
 * classes, {@code StartSetPlay} and {@code hsl.HslStartSetPlay}: two set-play procedures and two
 * kinds ({@code SecondaryState}, {@code hsl.SetPlay})</td></tr>
 * </table>
 * <p>
 * May depend on: protocol; no threads, files or sockets (ArchitectureTest).
 */
package touchline.game;
