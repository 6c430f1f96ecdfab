package touchline.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import touchline.record.PlaybackClock;
import touchline.record.Player;
import touchline.record.Recording;
import touchline.record.RecordingException;
import touchline.record.ReplayNotes;
import touchline.record.TimelineEvent;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;

/**
 * {@code touchline replay FILE}: plays a recording through the same Envelope stream as live
 * traffic. Here, without a window, each envelope becomes one text line, as {@code listen}
 * prints live traffic; {@code --headless} plays as fast as possible, otherwise at
 * {@code --speed} times real time. Problems with the file are reported, what is readable plays.
 */
@Command(name = "replay", mixinStandardHelpOptions = true,
        description = "Replay an MCAP recording, printing one line per envelope.")
public final class ReplayCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "FILE", description = "the recording (.mcap)")
    Path file;

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

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Recording recording;
        try {
            recording = Recording.open(file);
        } catch (RecordingException e) {
            err.println("touchline replay: " + e.getMessage());
            return 1;
        }
        try (recording) {
            if (info) {
                return info(recording, out, err);
            }
            ReplayNotes opened = recording.notes();
            java.util.Set<String> noted = new java.util.HashSet<>(opened.problems());
            opened.problems().forEach(p -> err.println("note: " + p));
            opened.contents().forEach(c -> err.println("note: the file holds " + c + " (listed, not played)"));
            EnvelopeLine text = new EnvelopeLine();
            if (events) {
                for (TimelineEvent e : recording.events()) {
                    out.printf("event %+.1f s %s %s%n", (e.timeMicros() - recording.startMicros()) / 1e6, e.type(), e.label());
                }
            }
            Player player = new Player(recording, e -> out.println(text.format(e)), PlaybackClock.system());
            player.seek(recording.startMicros() + (long) (from * 1e6));
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
            ReplayNotes played = recording.notes();
            played.problems().stream().filter(noted::add).forEach(p -> err.println("note: " + p));
            played.skippedLine().ifPresent(p -> err.println("note: " + p));
            err.printf("replayed %d envelopes, %.1f s of recording%n", n, recording.durationMicros() / 1e6);
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
