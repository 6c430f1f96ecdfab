/**
 * Recording and replay in MCAP: the writer and reader ({@code McapWriter}, {@code McapReader}; the reader's parts:
 * {@code SummarySection}, {@code LinearScan} for a file without one, {@code ChunkAdmission} weighing chunks against
 * the {@code ExpansionLimit}, {@code ChunkHeader} decompressing and checking a chunk), the mapping of an
 * {@code Envelope} to channels and back ({@code EnvelopeWriter}, {@code Recording}), the recorder subscribed to
 * the stream ({@code Recorder}), playback paced by a clock ({@code Player}, {@code ReplaySession} for several
 * files on one timeline, {@code ClockAlignment}), timeline events ({@code TimelineEvent}), what a replay has to
 * say about its file ({@code ReplayNotes}), recovery of an unfinished file ({@code Recovery}) and CSV exports
 * ({@code DebugCsvExport}, {@code ChannelCsvExport}).
 * <p>
 * May depend on: transport, security and protocol; not model.
 */
package touchline.record;
