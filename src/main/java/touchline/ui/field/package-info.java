/**
 * The field: robots from above ({@code FieldView}), the region overlay ({@code RegionOverlayView}) and objects
 * around a robot ({@code RelativePositionsView}); the frame chooser both offer for ROS 2 robots ({@code FrameChooser}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.field;
