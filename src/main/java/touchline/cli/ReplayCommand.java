package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.record.Player;
import touchline.protocol.MessageKinds;
import touchline.record.RecordingException;
import touchline.record.Recording;
import touchline.record.ReplayNotes;
import touchline.record.ReplaySession;
import touchline.record.TimelineEvent;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

/**
 * {@code touchline replay FILE...}: plays one recording, or several (the laptop's and robots'
 * own logs) as one session in one merged order of time, through the same Envelope stream as
 * live traffic. Here, without a window, each envelope becomes one text line, as {@code listen}
 * prints live traffic; {@code --headless} plays as fast as possible, otherwise at
 * {@code --speed} times real time. Several files: each file's clock is aligned to the first's
 * by {@code --offset FILE=SECONDS} or else by the GameController packets both heard, and how
 * well is printed per file. Problems with the files are reported, what is readable plays.
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Replay MCAP recordings (several files: one session on one timeline), printing one line per envelope.")
public final class ReplayCommand implements Callable<Integer> {

    @Parameters(index = "0..*", arity = "1..*", paramLabel = "FILE",
            description = "the recording(s) (.mcap); several play as one session, aligned to the first file's clock")
    List<Path> files;

    @Option(names = "--offset", paramLabel = "FILE=SECONDS",
            description = "FILE's clock minus the first file's, e.g. robot3.mcap=+1.250 (instead of aligning by the "
                    + "GameController packets both files heard)")
    Map<String, String> offsets = new LinkedHashMap<>();

    @Option(names = "--speed", defaultValue = "1", description = "playback speed, 0.1 to 50 (default: ${DEFAULT-VALUE})")
    double speed;

    @Option(names = "--headless", description = "as fast as possible, no pacing")
    boolean headless;

    @Option(names = "--from", paramLabel = "SECONDS", description = "start this many seconds into the recording")
    double from;

    @Option(names = "--events", description = "list the timeline events (goals, state changes, robots lost) first")
    boolean events;

    @Option(names = "--info", description = "list what the file holds (channels, attachments, metadata) and what"
            + " replay would skip, without playing it")
    boolean info;

    @CommandLine.Mixin
    ExpansionOption expansion = new ExpansionOption();

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Map<Path, Long> given = new HashMap<>();
        for (Map.Entry<String, String> o : offsets.entrySet()) {
            Path file = files.stream().filter(f -> f.toString().equals(o.getKey())
                    || f.getFileName().toString().equals(o.getKey())).findFirst().orElse(null);
            if (file == null) {
                err.println("touchline replay: --offset " + o.getKey() + "=...: " + o.getKey() + " is not one of the files");
                return 2;
            }
            try {
                given.put(file, Math.round(Double.parseDouble(o.getValue().trim()) * 1e6));
            } catch (NumberFormatException e) {
                err.println("touchline replay: --offset " + o.getKey() + "=" + o.getValue()
                        + ": the offset is seconds, e.g. +1.250 or -0.3");
                return 2;
            }
        }
        touchline.record.ExpansionLimit limit = expansion.limit(err, "replay");
        if (limit == null) {
            return 2;
        }
        ReplaySession session;
        try {
            session = ReplaySession.open(files, given, new MessageKinds(), limit);
        } catch (RecordingException e) {
            err.println("touchline replay: " + e.getMessage());
            return 1;
        }
        try (session) {
            if (info) {
                for (ReplaySession.Part p : session.parts()) {
                    if (session.parts().size() > 1) {
                        out.println("file " + p.name() + ":");
                    }
                    info(p.recording(), out, err);
                }
                return 0;
            }
            boolean several = session.parts().size() > 1;
            if (several) {
                for (ReplaySession.Part p : session.parts()) {
                    err.println("file " + p.name() + ": " + p.offset().describe());
                }
            }
            ReplayNotes opened = session.notes();
            java.util.Set<String> noted = new java.util.HashSet<>(opened.problems());
            opened.problems().forEach(p -> err.println("note: " + p));
            opened.contents().forEach(c -> err.println("note: the file holds " + c + " (listed, not played)"));
            EnvelopeLine text = new EnvelopeLine();
            if (events) {
                for (TimelineEvent e : session.events()) {
                    out.printf("event %+.1f s %s %s%n", (e.timeMicros() - session.startMicros()) / 1e6, e.type(), e.label());
                }
            }
            Player[] playing = new Player[1];
            // The real clock, made once for this command (it has no console): the replay's pacing.
            Player player = new Player(session, e -> out.println(several
                    ? text.format(e) + " file=" + playing[0].deliveringSource() : text.format(e)), new touchline.app.SystemClock());
            playing[0] = player;
            player.seek(session.startMicros() + (long) (from * 1e6));
            long n;
            if (headless) {
                n = player.runToEnd();
            } else {
                player.setSpeed(speed);
                player.play();
                while (!player.snapshot().finished()) {
                    long wait = player.pump();
                    out.flush();
                    if (wait > 0) {
                        Thread.sleep(Math.max(1, Math.min(wait / 1_000_000L, 50)));
                    }
                }
                n = player.snapshot().emitted();
            }
            out.flush();
            // what playing found (a corrupt chunk, a channel of another tool): said, never dropped
            ReplayNotes played = session.notes();
            played.problems().stream().filter(noted::add).forEach(p -> err.println("note: " + p));
            played.skippedLine().ifPresent(p -> err.println("note: " + p));
            err.printf("replayed %d envelopes, %.1f s of recording%s%n", n, session.durationMicros() / 1e6,
                    several ? " from " + session.parts().size() + " files" : "");
            return 0;
        }
    }

    /** {@code --info}: the channels with their message counts and encodings, attachments, metadata, notes. */
    private static int info(Recording recording, PrintWriter out, PrintWriter err) {
        touchline.record.McapReader mcap = recording.mcap();
        if (!mcap.messageCountsFinal()) {
            touchline.record.McapReader.Cursor all = mcap.cursor(0);
            while (all.next() != null) {
                // counts every channel's messages, block by block
            }
        }
        out.printf("%s, %.1f s, %s%n", mcap.indexed() ? "finished (indexed)" : "unfinished (no summary; scanned)",
                recording.durationMicros() / 1e6, mcap.messageCount() >= 0 ? mcap.messageCount() + " messages"
                        : "message count unknown");
        mcap.channels().values().stream().sorted(java.util.Comparator.comparingInt(
                touchline.record.McapReader.ChannelInfo::id)).forEach(c -> {
                    touchline.record.McapReader.Schema s = mcap.schemas().get(c.schemaId());
                    out.printf("channel %s (%s/%s) %d messages%n", c.topic(), s == null ? "no schema" : s.encoding()
                            + " " + s.name(), c.messageEncoding(), mcap.messages(c.id()));
                });
        ReplayNotes notes = recording.notes();
        notes.contents().forEach(out::println);
        notes.lines().forEach(p -> err.println("note: " + p));
        return 0;
    }

}
