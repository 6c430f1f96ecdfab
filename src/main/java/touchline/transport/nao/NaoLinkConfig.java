package touchline.transport.nao;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;

/**
 * Per-method rules of a {@link NaoLink}, loaded from a Java properties file (see
 * {@code samples/nao.properties}): default and per-method timeouts, minimum intervals between
 * calls of one method, which methods are idempotent (read-only, safe to retry),
 * and the retry count. Method names are {@code Module.method} or {@code *.method} for every
 * module. A broken entry never stops the console: it is skipped, reported in
 * {@link #problems()}, and the default stays in force.
 */
public final class NaoLinkConfig {

    /** Lazy Pirate's 2500 ms: long enough for a loaded robot, short enough to notice a hang. */
    public static final long DEFAULT_TIMEOUT_MS = 2500;
    public static final int DEFAULT_RETRIES = 2;

    private final long defaultTimeoutMs;
    private final int retries;
    private final Map<String, Long> timeouts;
    private final Map<String, Long> intervals;
    private final Set<String> idempotent;
    private final List<String> problems;

    private NaoLinkConfig(long defaultTimeoutMs, int retries, Map<String, Long> timeouts,
                          Map<String, Long> intervals, Set<String> idempotent, List<String> problems) {
        this.defaultTimeoutMs = defaultTimeoutMs;
        this.retries = retries;
        this.timeouts = Map.copyOf(timeouts);
        this.intervals = Map.copyOf(intervals);
        this.idempotent = Set.copyOf(idempotent);
        this.problems = List.copyOf(problems);
    }

    /** The built-in rules: the same as the shipped samples/nao.properties. */
    public static NaoLinkConfig defaults() {
        return parse(DEFAULT_TEXT, "built-in defaults");
    }

    /** Loads a file; a missing or unreadable file gives the defaults with one problem saying why. */
    public static NaoLinkConfig load(Path file) {
        try {
            return parse(Files.readString(file, StandardCharsets.UTF_8), file.toString());
        } catch (IOException | java.io.UncheckedIOException e) {
            NaoLinkConfig d = defaults();
            List<String> p = new ArrayList<>(d.problems);
            p.add(file + ": cannot read (" + e.getMessage() + "); using the built-in defaults");
            return new NaoLinkConfig(d.defaultTimeoutMs, d.retries, d.timeouts, d.intervals, d.idempotent, p);
        }
    }

    public static NaoLinkConfig parse(String text, String source) {
        Properties props = new Properties();
        List<String> problems = new ArrayList<>();
        try (Reader r = new StringReader(text)) {
            props.load(r);
        } catch (IOException | IllegalArgumentException e) {
            // e.g. a malformed unicode escape. The built-in text always loads, so this cannot recurse.
            NaoLinkConfig d = defaults();
            return new NaoLinkConfig(d.defaultTimeoutMs, d.retries, d.timeouts, d.intervals, d.idempotent,
                    List.of(source + ": not a readable properties file (" + e.getMessage() + "); using the built-in defaults"));
        }
        long defaultTimeout = DEFAULT_TIMEOUT_MS;
        int retries = DEFAULT_RETRIES;
        Map<String, Long> timeouts = new HashMap<>();
        Map<String, Long> intervals = new HashMap<>();
        Set<String> idempotent = new HashSet<>();
        for (String key : new java.util.TreeSet<>(props.stringPropertyNames())) {
            String value = props.getProperty(key).strip();
            String where = source + ": " + key + "=" + value + ": ";
            try {
                if (key.equals("timeout.default")) {
                    defaultTimeout = positive(value);
                } else if (key.equals("retries")) {
                    long n = Long.parseLong(value);
                    if (n < 0 || n > 10) {
                        throw new IllegalArgumentException("must be 0..10");
                    }
                    retries = (int) n;
                } else if (key.startsWith("timeout.")) {
                    timeouts.put(methodName(key.substring("timeout.".length())), positive(value));
                } else if (key.startsWith("interval.")) {
                    intervals.put(methodName(key.substring("interval.".length())), positive(value));
                } else if (key.equals("idempotent")) {
                    for (String m : value.split("[,\\s]+")) {
                        if (!m.isEmpty()) {
                            idempotent.add(methodName(m));
                        }
                    }
                } else {
                    problems.add(where + "unknown key (expected timeout.default, timeout.M.m, interval.M.m, idempotent, retries); ignored");
                }
            } catch (IllegalArgumentException e) {
                problems.add(where + e.getMessage() + "; ignored");
            }
        }
        return new NaoLinkConfig(defaultTimeout, retries, timeouts, intervals, idempotent, problems);
    }

    private static long positive(String value) {
        long n;
        try {
            n = Long.parseLong(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("not a whole number of milliseconds");
        }
        if (n <= 0) {
            throw new IllegalArgumentException("must be > 0 ms");
        }
        return n;
    }

    private static String methodName(String name) {
        int dot = name.lastIndexOf('.');
        if (dot <= 0 || dot == name.length() - 1) {
            throw new IllegalArgumentException("'" + name + "' is not Module.method or *.method");
        }
        return name;
    }

    private static <T> T lookup(Map<String, T> map, NaoCall call) {
        T v = map.get(call.qualifiedName());
        return v != null ? v : map.get("*." + call.method());
    }

    public long timeoutMillis(NaoCall call) {
        Long t = lookup(timeouts, call);
        return t != null ? t : defaultTimeoutMs;
    }

    /** Minimum time between two sends of this method, 0 when unlimited. */
    public long minIntervalMillis(NaoCall call) {
        Long t = lookup(intervals, call);
        return t != null ? t : 0;
    }

    public boolean isIdempotent(NaoCall call) {
        return idempotent.contains(call.qualifiedName()) || idempotent.contains("*." + call.method());
    }

    public int retries() {
        return retries;
    }

    public long defaultTimeoutMillis() {
        return defaultTimeoutMs;
    }

    /** What was wrong with the source, one line per problem; empty when it was clean. */
    public List<String> problems() {
        return problems;
    }

    // Kept in sync with samples/nao.properties (NaoLinkConfigTest checks it).
    static final String DEFAULT_TEXT = """
            timeout.default=2500
            retries=2
            timeout.ALRobotPosture.goToPosture=15000
            timeout.ALRobotPosture.applyPosture=15000
            timeout.ALMotion.moveInit=10000
            timeout.ALMotion.wakeUp=10000
            timeout.ALMotion.rest=10000
            timeout.ALMotion.angleInterpolation=15000
            timeout.ALMotion.angleInterpolationWithSpeed=15000
            timeout.ALMotion.walkTo=30000
            timeout.ALMotion.moveTo=30000
            timeout.ALTextToSpeech.say=30000
            interval.ALMotion.setAngles=200
            interval.ALMotion.changeAngles=200
            interval.ALMotion.moveToward=100
            interval.ALMotion.move=100
            interval.ALMotion.setWalkTargetVelocity=100
            idempotent=*.getMethodList *.getMethodHelp *.getModuleHelp *.getUsage *.version *.ping \
              ALMemory.getData ALMemory.getDataList ALMemory.getListData ALMotion.getAngles \
              ALMotion.getStiffnesses ALMotion.getRobotPosition ALMotion.getRobotVelocity \
              ALMotion.getSummary ALMotion.moveIsActive ALRobotPosture.getPosture \
              ALRobotPosture.getPostureList ALTextToSpeech.getVolume ALTextToSpeech.getLanguage \
              ALBattery.getBatteryCharge
            """;
}
