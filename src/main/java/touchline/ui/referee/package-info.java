/**
 * The referee's tab: the GameController tab ({@code GameControllerTab}, {@code GameControllerView}) and the HSL
 * referee box, its model without JavaFX ({@code HslRefereeModel}) and its view ({@code HslRefereeView}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.referee;
