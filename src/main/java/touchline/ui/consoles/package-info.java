/**
 * The consoles: the debug console ({@code DebugConsoleView}), the network console ({@code NetworkView}), an option's
 * text, table and raw message ({@code TextView}, {@code TableDataView}, {@code RawDataView}), and the log lists
 * they share ({@code LogList}, {@code NewestLines}, {@code RingFollower}).
 * <p>
 * May depend on: as ui.
 */
package touchline.ui.consoles;
