/**
 * The window: {@code ConsoleWindow}, the docking area ({@code Shell}), the views' registry ({@code ViewRegistry},
 * {@code ViewSpec}) and what a view may take ({@code ViewContext}), named layouts ({@code LayoutNode},
 * {@code LayoutCodec}, {@code LayoutStore}), menus ({@code LayoutMenu}, {@code HelpMenu}) and shortcuts, dialogs,
 * quick-open, help, the status bar and the user's settings ({@code SettingsFile}, {@code WindowPlaces}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.window;
