/**
 * Serving this console to remote viewers: the viewers view ({@code ViewersView}) and the window's
 * <i>Serve to viewers</i> toggle ({@code ServeToggle}), both over {@code app.LiveServing}.
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.viewers;
