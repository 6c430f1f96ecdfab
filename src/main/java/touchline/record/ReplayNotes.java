package touchline.record;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Collectors;

/**
 * Everything a replay has to say about its file, one value read alike by {@code replay},
 * {@code export} and the window's replay panel: what is wrong with the file
 * ({@link #problems}), what was skipped channel by channel with a count and the reason
 * ({@link #skipped}), and what the file holds besides messages (attachments and metadata
 * records, which are listed, not played).
 *
 * @param complete true once every chunk has been read, so the skipped counts are final
 */
public record ReplayNotes(List<String> problems, List<SkippedChannel> skipped, List<McapReader.Attachment> attachments,
                          Map<String, Map<String, String>> metadata, boolean complete) {

    /** A channel whose messages are not played: its topic, schema/message encoding, why, how many messages so far. */
    public record SkippedChannel(String topic, String encoding, String reason, long messages) {

        @Override
        public String toString() {
            return topic + " (" + encoding + ": " + reason + ") " + String.format(Locale.ROOT, "%,d", messages);
        }
    }

    public static final ReplayNotes NONE = new ReplayNotes(List.of(), List.of(), List.of(), Map.of(), true);

    public ReplayNotes {
        problems = List.copyOf(problems);
        skipped = List.copyOf(skipped);
        attachments = List.copyOf(attachments);
        metadata = Map.copyOf(metadata);
    }

    /** These notes and {@code other}'s, as for several files played on one timeline. */
    public ReplayNotes plus(ReplayNotes other) {
        List<String> p = new ArrayList<>(problems);
        p.addAll(other.problems);
        List<SkippedChannel> s = new ArrayList<>(skipped);
        s.addAll(other.skipped);
        List<McapReader.Attachment> a = new ArrayList<>(attachments);
        a.addAll(other.attachments);
        Map<String, Map<String, String>> m = new java.util.HashMap<>(metadata);
        m.putAll(other.metadata);
        return new ReplayNotes(p, s, a, m, complete && other.complete);
    }

    /** The same notes said of one file among several: problems, topics, attachments and metadata named with {@code file}. */
    public ReplayNotes inFile(String file) {
        Map<String, Map<String, String>> m = new java.util.HashMap<>();
        // Touchline's own format record is never listed; the file's version has been said as a problem if it matters
        metadata.forEach((k, v) -> {
            if (!k.equals(McapWriter.FORMAT_METADATA)) {
                m.put(file + ": " + k, v);
            }
        });
        return new ReplayNotes(problems.stream().map(p -> file + ": " + p).toList(),
                skipped.stream().map(k -> new SkippedChannel(file + ": " + k.topic(), k.encoding(), k.reason(),
                        k.messages())).toList(),
                attachments.stream().map(x -> new McapReader.Attachment(file + ": " + x.name(), x.mediaType(), x.size(),
                        x.logTime())).toList(), m, complete);
    }

    public long skippedMessages() {
        return skipped.stream().mapToLong(SkippedChannel::messages).sum();
    }

    /** e.g. "skipped 120 messages of 2 channels: /odom (ros2msg/cdr: encoding not supported) 60, ..." */
    public Optional<String> skippedLine() {
        if (skipped.isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(String.format(Locale.ROOT, "skipped %,d messages%s of %d channel%s: ", skippedMessages(),
                complete ? "" : " so far", skipped.size(), skipped.size() == 1 ? "" : "s")
                + skipped.stream().map(SkippedChannel::toString).collect(Collectors.joining(", ")));
    }

    /** Every note as one user-facing sentence: the file's problems, then what was skipped. */
    public List<String> lines() {
        List<String> all = new ArrayList<>(problems);
        skippedLine().ifPresent(all::add);
        return all;
    }

    /** What the file holds besides messages: one line per attachment and per metadata record (not Touchline's own). */
    public List<String> contents() {
        List<String> out = new ArrayList<>();
        for (McapReader.Attachment a : attachments) {
            out.add(String.format(Locale.ROOT, "attachment %s (%s, %,d bytes)", a.name(),
                    a.mediaType().isEmpty() ? "no media type" : a.mediaType(), a.size()));
        }
        metadata.entrySet().stream().filter(e -> !e.getKey().equals(McapWriter.FORMAT_METADATA))
                .sorted(Map.Entry.comparingByKey())
                .forEach(e -> out.add("metadata " + e.getKey() + ": " + e.getValue().entrySet().stream()
                        .map(kv -> kv.getKey() + "=" + kv.getValue()).collect(Collectors.joining(", "))));
        return out;
    }

    /** A short line for a badge: "" when there is nothing to say. */
    public String badge() {
        if (problems.isEmpty() && skipped.isEmpty()) {
            return "";
        }
        List<String> parts = new ArrayList<>();
        if (!problems.isEmpty()) {
            parts.add(problems.size() + (problems.size() == 1 ? " problem with the file" : " problems with the file"));
        }
        if (!skipped.isEmpty()) {
            parts.add(String.format(Locale.ROOT, "%,d messages of %d channel%s skipped", skippedMessages(),
                    skipped.size(), skipped.size() == 1 ? "" : "s"));
        }
        return "⚠ " + String.join(" · ", parts);
    }
}
