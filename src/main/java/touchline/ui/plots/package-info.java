/**
 * The plots: an option's series ({@code PlotView}), any numeric field of any message kind ({@code FieldPlotView})
 * and an option's image ({@code ImageDataView}); their drawing is in {@code ui.render}.
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.plots;
