package touchline.cli;

import picocli.CommandLine.Option;
import touchline.record.ExpansionLimit;

/**
 * {@code --max-expansion RATIO}, shared by the commands that read recordings (replay, recover,
 * export): how far a file's chunks may expand beyond its own size before the rest is refused.
 */
final class ExpansionOption {

    @Option(names = "--max-expansion", paramLabel = "RATIO", defaultValue = "" + ExpansionLimit.DEFAULT_RATIO,
            description = "read chunks holding up to RATIO times the file's size more than the file (at least 16 MB,"
                    + " at most RATIO x 256 MB); what lies beyond is refused and said (default: ${DEFAULT-VALUE})")
    int ratio;

    /** The limit asked for, or null (said) when the ratio is below 1. */
    ExpansionLimit limit(java.io.PrintWriter err, String command) {
        if (ratio < 1) {
            err.println("touchline " + command + ": --max-expansion is at least 1, not " + ratio);
            return null;
        }
        return new ExpansionLimit(ratio);
    }
}
