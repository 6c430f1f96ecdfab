/**
 * Record and replay in one view ({@code ReplayView}): the recording panel ({@code RecordPanel}), the timeline
 * ({@code TimelineCanvas}) and one background thread for slow file work ({@code WorkQueue}); what the view decides
 * (files to open or why not, the loop marks, the position and notes lines) is the FX-free {@code ReplayViewModel}.
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.replay;
