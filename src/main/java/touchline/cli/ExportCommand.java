package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.record.DebugCsvExport;
import touchline.record.Recording;
import touchline.record.RecordingException;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/** {@code touchline export FILE --robot N --kind debugPlot|debugTable --csv}: one robot's plots or tables as CSV. */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = "Export a robot's plots (debugPlot) or tables (debugTable) from a recording as CSV.")
public final class ExportCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE", description = "the recording (.mcap)")
    Path file;

    @Option(names = "--robot", required = true, description = "robot ID")
    int robot;

    @Option(names = "--kind", required = true, description = "debugPlot or debugTable")
    String kind;

    @Option(names = "--csv", description = "CSV output (the only format so far)")
    boolean csv = true;

    @Option(names = "--out", description = "output file (default: standard output)")
    Path out;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        DebugCsvExport.Kind what;
        try {
            what = DebugCsvExport.Kind.parse(kind);
        } catch (IllegalArgumentException e) {
            err.println("touchline export: " + e.getMessage());
            return 2;
        }
        Recording recording;
        try {
            recording = Recording.open(file);
        } catch (RecordingException e) {
            err.println("touchline export: " + e.getMessage());
            return 1;
        }
        try (recording) {
            long rows;
            if (out != null) {
                try (Writer w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
                    rows = new DebugCsvExport(recording).write(robot, what, w);
                }
            } else {
                PrintWriter w = spec.commandLine().getOut();
                rows = new DebugCsvExport(recording).write(robot, what, w);
                w.flush();
            }
            // the same notes replay prints: what was skipped, and what a CSV cannot hold
            touchline.record.ReplayNotes notes = recording.notes();
            notes.lines().forEach(p -> err.println("note: " + p));
            notes.contents().forEach(c -> err.println("note: the file holds " + c
                    + ", which a CSV export does not carry (touchline replay --info lists it)"));
            err.println("exported " + rows + " rows" + (rows == 0 ? " (robot " + robot + " sent no " + kind + ")" : ""));
        }
        return 0;
    }

}
