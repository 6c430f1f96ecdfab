package touchline.transport;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;

/**
 * Keeps the UDP pipeline's two threads on different cores: the event loop on the first half of
 * the CPUs this process may use, {@code touchline-decode} on the second half. Each hands its
 * datagrams to the other, and when one wakes the other, Linux often puts the woken thread on the
 * waker's core while the other core idles; both then wait for one core until the load balancer
 * moves one, milliseconds later — a burst of datagrams is half over by then. Measured on two
 * cores (`bench ingest --threads`): each thread waited for a core ~30 % of a drain; split, the
 * console's pipeline went from 0.79 to 0.93–1.13 of the bare parse loop (docs/benchmarks.md,
 * issue 11). Every other thread (the window's, the GC's) runs anywhere as before.
 *
 * <p>Linux only, best effort, with {@code taskset} (util-linux) on each thread's id; nothing
 * happens with fewer than two CPUs, elsewhere, or with {@code -Dtouchline.udp.cores=shared}.
 * What was done (or why not) is part of the transport's description, shown at start and in
 * Help → About.
 *
 * @param eventLoopCpus the event loop's CPUs as taskset takes them, e.g. {@code 0} or {@code 0-3}
 * @param stageCpus     the stage's CPUs
 */
public record CoreSplit(String eventLoopCpus, String stageCpus) {

    /** The system property: {@code split} (default) or {@code shared} (no affinity set). */
    public static final String PROPERTY = "touchline.udp.cores";

    /**
     * The split for a process allowed on {@code cpus} (ascending): the first half (rounded down)
     * for the event loop, the rest for the stage; empty with fewer than two.
     */
    public static Optional<CoreSplit> of(List<Integer> cpus) {
        if (cpus.size() < 2) {
            return Optional.empty();
        }
        int half = cpus.size() / 2;
        return Optional.of(new CoreSplit(listText(cpus.subList(0, half)), listText(cpus.subList(half, cpus.size()))));
    }

    /**
     * The CPUs of a {@code Cpus_allowed_list} line of {@code /proc/self/status}, e.g.
     * {@code 0-3,6,8-9}, ascending; throws IllegalArgumentException for anything else.
     */
    public static List<Integer> parseCpuList(String list) {
        List<Integer> cpus = new ArrayList<>();
        for (String part : list.trim().split(",")) {
            String[] range = part.trim().split("-", -1);
            if (range.length > 2 || range[0].isEmpty()) {
                throw new IllegalArgumentException("not a CPU list: \"" + list + "\"");
            }
            int from = Integer.parseInt(range[0]);
            int to = range.length == 2 ? Integer.parseInt(range[1]) : from;
            if (from < 0 || to < from || to > 4095) {
                throw new IllegalArgumentException("not a CPU list: \"" + list + "\"");
            }
            for (int c = from; c <= to; c++) {
                if (cpus.isEmpty() || c > cpus.get(cpus.size() - 1)) {
                    cpus.add(c);
                }
            }
        }
        return cpus;
    }

    /** {@code [0,1,2,5]} → {@code 0-2,5}. */
    static String listText(List<Integer> cpus) {
        StringBuilder out = new StringBuilder();
        for (int i = 0; i < cpus.size(); ) {
            int j = i;
            while (j + 1 < cpus.size() && cpus.get(j + 1) == cpus.get(j) + 1) {
                j++;
            }
            out.append(out.length() == 0 ? "" : ",").append(cpus.get(i));
            if (j > i) {
                out.append('-').append(cpus.get(j));
            }
            i = j + 1;
        }
        return out.toString();
    }

    /** "ingest threads on CPUs 0 | 1" for the transport's description. */
    public String describe() {
        return "ingest threads on CPUs " + eventLoopCpus + " | " + stageCpus;
    }

    /** The calling thread's kernel id (Linux: {@code /proc/thread-self}), or empty elsewhere. */
    static Optional<String> currentThreadId() {
        try {
            return Optional.of(Files.readSymbolicLink(Path.of("/proc/thread-self")).getFileName().toString());
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return Optional.empty();
        }
    }

    /**
     * For this process now: the split of the CPUs it may use, or why there is none (a sentence
     * for the transport's description; empty when asked not to split).
     */
    static Result forThisProcess() {
        if ("shared".equalsIgnoreCase(System.getProperty(PROPERTY, "split").trim())) {
            return new Result(Optional.empty(), "");
        }
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("Cpus_allowed_list:")) {
                    List<Integer> cpus = parseCpuList(line.substring(line.indexOf(':') + 1));
                    Optional<CoreSplit> split = of(cpus);
                    return new Result(split, split.isPresent() ? "" : "one CPU: ingest threads share it");
                }
            }
            return new Result(Optional.empty(), "");
        } catch (IOException | RuntimeException notLinux) {
            return new Result(Optional.empty(), "");
        }
    }

    /** A split to apply, or a note why none (empty when there is nothing to say). */
    record Result(Optional<CoreSplit> split, String note) { }

    /**
     * Sets the two threads' affinity; returns what to show: this split's description, or why
     * it could not be set (the threads then run anywhere, as without it).
     */
    String apply(String eventLoopThreadId, String stageThreadId) {
        String failed = taskset(eventLoopCpus, eventLoopThreadId);
        if (failed == null) {
            failed = taskset(stageCpus, stageThreadId);
        }
        return failed == null ? describe() : "ingest threads not split across CPUs: " + failed;
    }

    /** Null when set, else why not. */
    private static String taskset(String cpus, String threadId) {
        try {
            Process p = new ProcessBuilder("taskset", "-p", "-c", cpus, threadId)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectErrorStream(true).start();
            if (!p.waitFor(5, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return "taskset did not answer within 5 s";
            }
            return p.exitValue() == 0 ? null : "taskset exited with " + p.exitValue();
        } catch (IOException e) {
            return "taskset not found (util-linux)";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }
}
