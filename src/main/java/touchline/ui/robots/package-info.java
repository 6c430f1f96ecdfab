/**
 * The robots feature: every robot seen, one row each ({@code RobotsView}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.robots;
