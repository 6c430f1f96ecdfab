package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.protocol.MessageKinds;
import touchline.record.ChannelCsvExport;
import touchline.record.ChunkCompression;
import touchline.record.DebugCsvExport;
import touchline.record.Recording;
import touchline.record.RecordingException;
import touchline.record.foxglove.FoxgloveExport;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;

/**
 * {@code touchline export}: a recording for other tools. {@code --format foxglove --out F}: an
 * MCAP with the recorded channels and the Foxglove standard ones beside them;
 * {@code --format csv --channel TOPIC}: any channel as CSV; {@code --robot N --kind K --csv}:
 * one robot's plots or tables as CSV.
 */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = {"Export a recording for other tools:",
                "  --format foxglove --out OUT.mcap: the recording plus the Foxglove",
                "    standard channels (log, images, region annotations, 3D field)",
                "    that Foxglove and Lichtblick show in their own panels;",
                "  --format csv --channel TOPIC: any protobuf channel as CSV;",
                "  --robot N --kind debugPlot|debugTable --csv: a robot's plots or tables."})
public final class ExportCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE", description = "the recording (.mcap)")
    Path file;

    @Option(names = "--format", description = "csv (default) or foxglove")
    String format = "csv";

    @Option(names = "--channel", paramLabel = "TOPIC", description = "with --format csv: the channel (topic) to export, e.g. /robot/3/status")
    String channel;

    @Option(names = "--robot", description = "robot ID (with --kind)")
    Integer robot;

    @Option(names = "--kind", description = "debugPlot or debugTable (with --robot)")
    String kind;

    @Option(names = "--csv", description = "CSV output (same as --format csv)")
    boolean csv;

    @Option(names = "--out", description = "output file (default for CSV: standard output; required for foxglove)")
    Path out;

    @CommandLine.Mixin
    ExpansionOption expansion = new ExpansionOption();

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter err = spec.commandLine().getErr();
        String f = csv ? "csv" : format.toLowerCase(Locale.ROOT);
        if (!f.equals("csv") && !f.equals("foxglove")) {
            err.println("touchline export: --format is csv or foxglove, not '" + format + "'");
            return 2;
        }
        if (f.equals("foxglove") && out == null) {
            err.println("touchline export: --format foxglove writes an MCAP file: give it with --out OUT.mcap");
            return 2;
        }
        if (f.equals("csv") && channel == null && (robot == null || kind == null)) {
            err.println("touchline export: say what to export as CSV: --channel TOPIC, or --robot N --kind debugPlot|debugTable");
            return 2;
        }
        DebugCsvExport.Kind parsed = null;
        if (f.equals("csv") && channel == null) {
            try {
                parsed = DebugCsvExport.Kind.parse(kind);
            } catch (IllegalArgumentException e) {
                err.println("touchline export: " + e.getMessage());
                return 2;
            }
        }
        DebugCsvExport.Kind what = parsed;
        touchline.record.ExpansionLimit limit = expansion.limit(err, "export");
        if (limit == null) {
            return 2;
        }
        Recording recording;
        MessageKinds kinds = new MessageKinds();
        try {
            recording = Recording.open(file, kinds, limit);
        } catch (RecordingException e) {
            err.println("touchline export: " + e.getMessage());
            return 1;
        }
        try (recording) {
            int code;
            if (f.equals("foxglove")) {
                code = foxglove(recording, kinds, err);
            } else if (channel != null) {
                code = channelCsv(recording, err);
            } else {
                long rows = csv(w -> new DebugCsvExport(recording).write(robot, what, w));
                err.println("exported " + rows + " rows" + (rows == 0 ? " (robot " + robot + " sent no " + kind + ")" : ""));
                code = 0;
            }
            // the same notes replay prints: what was skipped, and what the export cannot hold
            touchline.record.ReplayNotes notes = recording.notes();
            notes.lines().forEach(p -> err.println("note: " + p));
            boolean foxgloveFormat = f.equals("foxglove");
            notes.contents().stream().filter(c -> !(foxgloveFormat && c.startsWith("metadata")))
                    .forEach(c -> err.println("note: the file holds " + c + ", which "
                            + (foxgloveFormat ? "the foxglove export does not copy" : "a CSV export does not carry")
                            + " (touchline replay --info lists it)"));
            return code;
        }
    }

    private int foxglove(Recording recording, MessageKinds kinds, PrintWriter err) throws IOException {
        FoxgloveExport.Result r;
        try (OutputStream o = Files.newOutputStream(out)) {
            r = new FoxgloveExport(kinds).write(recording, o, ChunkCompression.NONE);
        }
        err.println("exported " + r.copied() + " recorded messages (FUmanoids channels under " + FoxgloveExport.RECORDED_PREFIX
                + ") and " + r.standard() + " for the viewers' panels to " + out);
        r.standardByTopic().forEach((topic, n) -> err.println("  " + topic + ": " + n));
        if (r.skipped() > 0) {
            err.println("  " + r.skipped() + " images had no standard form (colour-class or mis-sized frames, unreadable camera replies)");
        }
        return 0;
    }

    private int channelCsv(Recording recording, PrintWriter err) throws IOException {
        ChannelCsvExport.Result[] r = new ChannelCsvExport.Result[1];
        try {
            csv(w -> {
                r[0] = new ChannelCsvExport(recording).write(channel, w);
                return r[0].rows();
            });
        } catch (NotExportableWrapper e) {
            err.println("touchline export: " + e.getCause().getMessage());
            if (out != null) {
                Files.deleteIfExists(out);
            }
            return 1;
        }
        err.println("exported " + r[0].rows() + " rows of " + channel
                + (r[0].undecodable() > 0 ? " (" + r[0].undecodable() + " messages did not decode and are left out)" : ""));
        return 0;
    }

    private interface CsvBody {
        long write(Writer w) throws IOException, ChannelCsvExport.NotExportable;
    }

    /** Carries a NotExportable out of a CSV body. */
    private static final class NotExportableWrapper extends IOException {
        NotExportableWrapper(ChannelCsvExport.NotExportable cause) {
            super(cause);
        }
    }

    private long csv(CsvBody body) throws IOException {
        try {
            if (out != null) {
                try (Writer w = Files.newBufferedWriter(out, StandardCharsets.UTF_8)) {
                    return body.write(w);
                }
            }
            PrintWriter w = spec.commandLine().getOut();
            long rows = body.write(w);
            w.flush();
            return rows;
        } catch (ChannelCsvExport.NotExportable e) {
            throw new NotExportableWrapper(e);
        }
    }
}
