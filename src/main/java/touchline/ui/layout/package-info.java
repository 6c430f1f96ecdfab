/**
 * Saved arrangements of views, independent of JavaFX: {@code LayoutNode}, their text form ({@code LayoutCodec})
 * and the directory they are kept in ({@code LayoutStore}).
 * <p>
 * May depend on: as ui (uses nothing of JavaFX).
 */
package touchline.ui.layout;
