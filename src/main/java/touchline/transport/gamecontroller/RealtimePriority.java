package touchline.transport.gamecontroller;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Best-effort real-time scheduling (SCHED_RR) for one thread on Linux, via {@code chrt} on the
 * thread's own id from {@code /proc/thread-self}. Java cannot do this itself, and on a
 * crowded match-day laptop it is what keeps the 500 ms GameController cadence within a
 * millisecond (see docs/benchmarks.md). Needs CAP_SYS_NICE (or root); without it, or off
 * Linux (macOS, Windows: normal priority is the portable fallback), or switched off with
 * {@code -Dtouchline.realtime=off}, nothing changes and the reason is returned.
 */
public final class RealtimePriority {

    private static final Logger LOG = LoggerFactory.getLogger(RealtimePriority.class);

    /** {@code -Dtouchline.realtime=off}: never ask (the portable path, forced on Linux in tests). */
    public static final String PROPERTY = "touchline.realtime";

    private final int priority;
    private final String osName;
    private final boolean allowed;

    /** @param priority SCHED_RR priority 1..99 (10 is plenty: above every normal thread) */
    public RealtimePriority(int priority) {
        this(priority, System.getProperty("os.name", ""), !"off".equalsIgnoreCase(System.getProperty(PROPERTY, "")));
    }

    /**
     * @param osName  the operating system ({@code os.name}); only Linux has SCHED_RR via chrt
     * @param allowed false when switched off: every thread keeps normal priority
     */
    public RealtimePriority(int priority, String osName, boolean allowed) {
        this.priority = priority;
        this.osName = osName;
        this.allowed = allowed;
    }

    /**
     * "" when this machine may give real-time priority (Linux, not switched off; the system can
     * still refuse), else why the portable fallback, normal priority, is used.
     */
    public String unavailable() {
        if (!allowed) {
            return "switched off (-D" + PROPERTY + "=off)";
        }
        if (!osName.startsWith("Linux")) {
            return "real-time priority only on Linux, this is " + (osName.isBlank() ? "another system" : osName);
        }
        return "";
    }

    /** Applies SCHED_RR to the calling thread; returns "" on success, else why not. */
    public String applyToCurrentThread() {
        String unavailable = unavailable();
        if (!unavailable.isEmpty()) {
            return unavailable;
        }
        try {
            Path self = Files.readSymbolicLink(Path.of("/proc/thread-self"));
            String tid = self.getFileName().toString();
            Process chrt = new ProcessBuilder("chrt", "-r", "-p", String.valueOf(priority), tid)
                    .redirectErrorStream(true).start();
            if (!chrt.waitFor(5, TimeUnit.SECONDS)) {
                chrt.destroyForcibly();
                return "chrt did not finish";
            }
            String out = new String(chrt.getInputStream().readAllBytes()).trim();
            if (chrt.exitValue() != 0) {
                LOG.warn("no real-time priority for {}: {}", Thread.currentThread().getName(), out);
                return out.isEmpty() ? "chrt failed" : out;
            }
            return "";
        } catch (IOException | UnsupportedOperationException e) {
            return "not available here: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }
}
