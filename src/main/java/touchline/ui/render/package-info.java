/**
 * Drawing helpers the views share, no view of their own: the pixel raster and its pane ({@code Raster},
 * {@code RasterPane}), crisp lines, label sprites and colour classes, the plot's drawing and decimation
 * ({@code PlotDrawing}, {@code ColumnDecimation}, {@code YAxes}), canvases that resize, fitted tables and text columns.
 * <p>
 * May depend on: as ui, but no ui.window and no feature package (ArchitectureTest).
 */
package touchline.ui.render;
