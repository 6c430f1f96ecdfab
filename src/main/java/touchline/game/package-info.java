/**
 * The referee's game as a library, pure. One engine for every league, {@code RefereeEngine}: a state changed
 * only by {@code LeagueAction}s (legality, undo, listeners), with what differs between leagues in a
 * {@code League} strategy ({@code HlLeague} here, {@code hsl.HslLeague}). The Humanoid League (and SPL) rules:
 * a refereed {@code Game} over a {@code GameState} (teams, players,
 * penalties, clocks) changed only by {@code Action}s ({@code ToReady}, {@code ToSet}, {@code ToPlaying}, {@code
 * Penalize}, {@code Goal}, {@code StartSetPlay}, ...), each answering an {@code Outcome}; league parameters
 * ({@code LeagueParams}), the text form of actions for the CLI and scripts ({@code ActionSyntax}) and undo ({@code
 * UndoHistory}). Time comes in through {@code GameClock}; {@code RefereedGame} is what senders and receivers need
 * of any league's game.
 * <p>
 * May depend on: protocol; no threads, files or sockets (ArchitectureTest).
 */
package touchline.game;
