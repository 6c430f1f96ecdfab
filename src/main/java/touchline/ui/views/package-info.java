/**
 * The views and their drawing: the robots table, options tree, debug and network consoles ({@code RobotsView},
 * {@code OptionsView}, {@code DebugConsoleView}, {@code NetworkView}), the visualisations of a robot's option
 * ({@code PlotView}, {@code FieldPlotView}, {@code FieldView}, {@code RegionOverlayView}, {@code ImageDataView},
 * {@code TableDataView}, {@code TextView}, {@code RawDataView}), serving to viewers ({@code ViewersView}), the ROS 2 robots' parameters ({@code ParametersView}) and their topics and services ({@code RosCommandsView}), and the
 * helpers that keep them cheap to draw ({@code Raster}, {@code PlotDrawing}, {@code FieldDrawingPainter} (a ROS 2 robot's markers), {@code LogList}, {@code NewestLines},
 * {@code LiveRows}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.views;
