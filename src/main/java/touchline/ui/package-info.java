/**
 * The window, a face over the application core, by feature: each feature's package holds its views, which bind
 * what their services hold ({@code robots}, {@code options}, {@code consoles}, {@code plots}, {@code field},
 * {@code replay}, {@code referee}, {@code nao}, {@code viewers}; the ROS 2 parameters get their own when they
 * come); {@code render} holds the drawing helpers the views share, {@code frame} the once-per-frame pull
 * ({@code FramePulse}, {@code View}, {@code ConsoleChanges}), {@code window} the window, its docking area, layouts,
 * menus, dialogs, quick-open, help and settings. Here: the entry point ({@code Launcher}, {@code TouchlineApp}).
 * Network threads never touch a JavaFX node.
 * <p>
 * Only {@code TouchlineApp} and {@code window.ConsoleWindow} compose: they know {@code app.Console}, everything
 * else takes its services.
 * <p>
 * May depend on: every layer below (app, serve, model, record, transport, game, security, protocol); nothing uses
 * it.
 */
package touchline.ui;
