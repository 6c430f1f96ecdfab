/**
 * A recording copied for other tools: Touchline's envelopes as Foxglove standard messages ({@code
 * StandardMessages}, {@code StandardMessage}) and the export that writes them beside the raw channels ({@code
 * FoxgloveExport}).
 * <p>
 * May depend on: the record layer and what it may use.
 */
package touchline.record.foxglove;
