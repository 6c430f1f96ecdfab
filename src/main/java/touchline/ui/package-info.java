/**
 * The window, a face over the application core: {@code TouchlineApp} and {@code ConsoleWindow}, the docking area
 * ({@code Shell}), the views' registry and frame ({@code ViewRegistry}, {@code ViewSpec}, {@code View}, {@code
 * ViewFrame}, {@code ViewContext}: the core's services a view may take), the one place the UI reads the model, once per frame ({@code FramePulse},
 * {@code FrameCap}, {@code ConsoleChanges}), the status bar ({@code StatusBar}, {@code ConsoleStatus}) and the
 * user's settings ({@code SettingsFile}, {@code WindowPlaces}). Network threads never touch a JavaFX node.
 * <p>
 * Only {@code TouchlineApp} and {@code ConsoleWindow} compose: they know {@code app.Console}, everything else takes
 * its services.
 * <p>
 * May depend on: every layer below (app, serve, model, record, transport, game, security, protocol); nothing uses
 * it.
 */
package touchline.ui;
