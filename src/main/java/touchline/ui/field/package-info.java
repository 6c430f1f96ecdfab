/**
 * The field: robots from above ({@code FieldView}), the region overlay ({@code RegionOverlayView}) and objects
 * around a robot ({@code RelativePositionsView}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.field;
