/**
 * The referee's tab: the GameController tab ({@code GameControllerTab}, which binds to its model without JavaFX
 * {@code GameControllerTabModel} and the form's {@code GameSetup}), the HL/SPL box ({@code GameControllerView})
 * and the HSL referee box, its model without JavaFX ({@code HslRefereeModel}) and its view ({@code HslRefereeView}).
 * A referee's action only enqueues to the game's owner; {@code RefereeOutcomes} takes its outcome at a frame.
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.referee;
