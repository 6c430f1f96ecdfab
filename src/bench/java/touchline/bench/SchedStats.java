package touchline.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;

/**
 * Where a drain's wall-clock time went, from the kernel's own books: for every thread of this
 * process (the JVM's GC and compiler threads included, which {@link ThreadCpu} cannot see) the
 * time it ran on a core and the time it was runnable but waited for one
 * ({@code /proc/self/task/TID/schedstat}: run time, run-queue wait, in nanoseconds). Summed
 * between {@link #begin} and {@link #end} by thread name, so a pipeline thread that waited for a
 * core while the GC or the compiler ran shows as such. Linux only; elsewhere it stays empty.
 */
final class SchedStats {

    /** Run and run-queue wait nanoseconds of one named thread (or group of threads). */
    record Times(long runNanos, long waitNanos) {
        Times plus(Times o) {
            return new Times(runNanos + o.runNanos, waitNanos + o.waitNanos);
        }
    }

    private static final Path TASKS = Path.of("/proc/self/task");
    private Map<String, Times> atBegin = Map.of();
    private final Map<String, Times> total = new TreeMap<>();

    void begin() {
        atBegin = snapshot();
    }

    void end() {
        Map<String, Times> now = snapshot();
        now.forEach((key, t) -> {
            Times before = atBegin.getOrDefault(key, new Times(0, 0));
            long run = t.runNanos - before.runNanos;
            long wait = t.waitNanos - before.waitNanos;
            if (run > 0 || wait > 0) {
                total.merge(name(key), new Times(Math.max(0, run), Math.max(0, wait)), Times::plus);
            }
        });
    }

    /** By thread name (numbered GC and compiler threads summed), every drain so far. */
    Map<String, Times> total() {
        return new TreeMap<>(total);
    }

    /** Thread id + name → times now; empty where /proc is not there. */
    private static Map<String, Times> snapshot() {
        Map<String, Times> out = new HashMap<>();
        try (var tasks = Files.list(TASKS)) {
            for (Path task : (Iterable<Path>) tasks::iterator) {
                try {
                    String comm = Files.readString(task.resolve("comm")).trim();
                    String[] f = Files.readString(task.resolve("schedstat")).trim().split("\\s+");
                    out.put(task.getFileName() + " " + comm, new Times(Long.parseLong(f[0]), Long.parseLong(f[1])));
                } catch (IOException | RuntimeException gone) {
                    // the thread ended between the listing and the read: nothing to count
                }
            }
        } catch (IOException notLinux) {
            return Map.of();
        }
        return out;
    }

    /** "1234 ZWorker#1" → "ZWorker#", "C2 CompilerThre" stays: threads of one kind summed. */
    private static String name(String key) {
        String comm = key.substring(key.indexOf(' ') + 1);
        return comm.replaceAll("\\d+$", "");
    }

    /** The threads that ran most, per datagram: {@code name run/wait ns} for the top {@code n}. */
    static String text(Map<String, Times> times, long datagrams, int n) {
        double per = 1.0 / Math.max(1, datagrams);
        StringBuilder out = new StringBuilder();
        times.entrySet().stream()
                .sorted((a, b) -> Long.compare(b.getValue().runNanos, a.getValue().runNanos))
                .limit(n)
                .forEach(e -> out.append(out.length() == 0 ? "" : ", ").append(e.getKey()).append(' ')
                        .append(Math.round(e.getValue().runNanos * per)).append('/')
                        .append(Math.round(e.getValue().waitNanos * per)));
        return out + " (ns run/waited for a core, per datagram)";
    }
}
