package touchline.record;

import touchline.proto.Fumanoid;
import touchline.transport.Envelope;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Exports one robot's DebugPlot or DebugTable messages from a recording as CSV. Plots: a
 * header {@code time,series...} (series named {@code option/series} when the robot plots
 * more than one option) and one row per message, empty cells for series it did not carry.
 * Tables: {@code time,option,header...} and one row per table row; a new header row is
 * written when a table's columns change. Time is seconds since the recording started.
 */
public final class DebugCsvExport {

    /** What to export. */
    public enum Kind {
        PLOT, TABLE;

        /** Accepts the kind names users type: debugPlot/plot, debugTable/table. */
        public static Kind parse(String name) {
            return switch (name.toLowerCase(Locale.ROOT)) {
                case "debugplot", "plot" -> PLOT;
                case "debugtable", "table" -> TABLE;
                default -> throw new IllegalArgumentException("export writes plots (debugPlot) and tables (debugTable), not '"
                        + name + "'");
            };
        }
    }

    private final Recording recording;

    public DebugCsvExport(Recording recording) {
        this.recording = recording;
    }

    /** Writes the CSV; returns the number of data rows. */
    public long write(int robotId, Kind kind, Writer out) throws IOException {
        return kind == Kind.PLOT ? plots(robotId, out) : tables(robotId, out);
    }

    private List<Fumanoid.Message> messages(int robotId, List<Long> times) {
        List<Fumanoid.Message> out = new ArrayList<>();
        Recording.Cursor c = recording.cursor(Long.MIN_VALUE);
        for (Envelope e = c.next(); e != null; e = c.next()) {
            if (e.robotId() == robotId && e.message() instanceof Fumanoid.Message m) {
                out.add(m);
                times.add(e.timeMicros());
            }
        }
        return out;
    }

    private long plots(int robotId, Writer out) throws IOException {
        List<Long> times = new ArrayList<>();
        List<Fumanoid.Message> all = messages(robotId, times);
        Map<String, Integer> columns = new LinkedHashMap<>();
        java.util.Set<String> options = new java.util.HashSet<>();
        for (Fumanoid.Message m : all) {
            if (m.hasExtension(Fumanoid.debugPlot)) {
                options.add(m.getExtension(Fumanoid.debugPlot).getOption());
            }
        }
        boolean qualify = options.size() > 1;
        for (Fumanoid.Message m : all) {
            if (m.hasExtension(Fumanoid.debugPlot)) {
                Fumanoid.DebugPlot p = m.getExtension(Fumanoid.debugPlot);
                for (Fumanoid.PlotSample s : p.getSamplesList()) {
                    columns.putIfAbsent(name(qualify, p.getOption(), s.getSeries()), columns.size());
                }
            }
        }
        out.write("time");
        for (String c : columns.keySet()) {
            out.write(',');
            out.write(cell(c));
        }
        out.write('\n');
        long rows = 0;
        String[] row = new String[columns.size()];
        for (int i = 0; i < all.size(); i++) {
            Fumanoid.Message m = all.get(i);
            if (!m.hasExtension(Fumanoid.debugPlot)) {
                continue;
            }
            Fumanoid.DebugPlot p = m.getExtension(Fumanoid.debugPlot);
            java.util.Arrays.fill(row, "");
            for (Fumanoid.PlotSample s : p.getSamplesList()) {
                row[columns.get(name(qualify, p.getOption(), s.getSeries()))] = Double.toString(s.getValue());
            }
            out.write(seconds(times.get(i)));
            for (String v : row) {
                out.write(',');
                out.write(v);
            }
            out.write('\n');
            rows++;
        }
        return rows;
    }

    private static String name(boolean qualify, String option, String series) {
        return qualify ? option + "/" + series : series;
    }

    private long tables(int robotId, Writer out) throws IOException {
        List<Long> times = new ArrayList<>();
        List<Fumanoid.Message> all = messages(robotId, times);
        List<String> header = null;
        long rows = 0;
        for (int i = 0; i < all.size(); i++) {
            Fumanoid.Message m = all.get(i);
            if (!m.hasExtension(Fumanoid.debugTable)) {
                continue;
            }
            Fumanoid.DebugTable t = m.getExtension(Fumanoid.debugTable);
            if (!t.getHeaderList().equals(header)) {
                header = t.getHeaderList();
                out.write("time,option");
                for (String h : header) {
                    out.write(',');
                    out.write(cell(h));
                }
                out.write('\n');
            }
            for (Fumanoid.TableRow r : t.getRowsList()) {
                out.write(seconds(times.get(i)));
                out.write(',');
                out.write(cell(t.getOption()));
                for (String c : r.getCellsList()) {
                    out.write(',');
                    out.write(cell(c));
                }
                out.write('\n');
                rows++;
            }
        }
        return rows;
    }

    private String seconds(long micros) {
        long d = micros - recording.startMicros();
        return String.format(Locale.ROOT, "%d.%06d", d / 1_000_000L, d % 1_000_000L);
    }

    static String cell(String s) {
        if (s.indexOf(',') < 0 && s.indexOf('"') < 0 && s.indexOf('\n') < 0 && s.indexOf('\r') < 0) {
            return s;
        }
        return '"' + s.replace("\"", "\"\"") + '"';
    }
}
