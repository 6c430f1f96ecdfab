/**
 * Record and replay in one view ({@code ReplayView}): the recording panel ({@code RecordPanel}), the timeline
 * ({@code TimelineCanvas}) and one background thread for slow file work ({@code WorkQueue}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.replay;
