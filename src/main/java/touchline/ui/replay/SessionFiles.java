package touchline.ui.replay;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The replay view's file field: one recording, or several separated by {@code ;} played as
 * one session, each optionally with its clock offset to the first file in seconds
 * ({@code laptop.mcap; robot3.mcap=+1.250}), as {@code touchline replay --offset} takes it.
 *
 * @param files   the files in order (the first gives the session's clock)
 * @param offsets the offsets given, µs (the file's clock minus the first file's)
 */
record SessionFiles(List<Path> files, Map<Path, Long> offsets) {

    private static final Pattern OFFSET = Pattern.compile("(.+?)\\s*=\\s*([+-]?\\d+(?:\\.\\d*)?)");

    /** Parses the field's text; a blank entry is ignored. */
    static SessionFiles parse(String text) {
        List<Path> files = new ArrayList<>();
        Map<Path, Long> offsets = new LinkedHashMap<>();
        for (String entry : text.split(";")) {
            String e = entry.trim();
            if (e.isEmpty()) {
                continue;
            }
            Matcher m = OFFSET.matcher(e);
            if (m.matches()) {
                Path f = Path.of(m.group(1).trim());
                files.add(f);
                offsets.put(f, Math.round(Double.parseDouble(m.group(2)) * 1e6));
            } else {
                files.add(Path.of(e));
            }
        }
        return new SessionFiles(List.copyOf(files), Map.copyOf(offsets));
    }

    /** The text for the field: files joined by "; ", each with its given offset. */
    String text() {
        List<String> parts = new ArrayList<>();
        for (Path f : files) {
            Long o = offsets.get(f);
            parts.add(o == null ? f.toString() : f + "=" + String.format(java.util.Locale.ROOT, "%+.3f", o / 1e6));
        }
        return String.join("; ", parts);
    }

    /** The same files with {@code more} appended (a file already there is not added twice). */
    SessionFiles plus(List<Path> more) {
        List<Path> all = new ArrayList<>(files);
        more.stream().filter(f -> !all.contains(f)).forEach(all::add);
        return new SessionFiles(List.copyOf(all), offsets);
    }

    /** How the field names the files, for messages: "a.mcap" or "a.mcap and 2 more". */
    String names() {
        String first = files.get(0).getFileName().toString();
        return files.size() == 1 ? first : first + " and " + (files.size() - 1) + " more";
    }
}
