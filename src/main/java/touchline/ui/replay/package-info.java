/**
 * Record and replay in one view ({@code ReplayView}, which only binds): the recording panel ({@code RecordPanel}),
 * the file row ({@code SessionPicker}), the message and skipped-notes ({@code ReplayNotesPane}), the timeline
 * ({@code TimelineCanvas}), the transport bar ({@code TransportBar}) and the team schemas ({@code SchemaPane}). What
 * the view does and shows is the FX-free {@code ReplayViewModel} (with the loop marks, {@code LoopMarks}); its slow
 * file work runs on one background thread ({@code WorkQueue}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.replay;
