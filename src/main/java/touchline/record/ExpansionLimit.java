package touchline.record;

/**
 * How far a recording may expand when it is read. What its chunks hold (their records,
 * uncompressed; a chunk that another chunk's index entry overlaps counts again) may exceed the
 * file's own size by {@code ratio} times that size, by at least {@value #FLOOR_MB} MB and by at
 * most {@code ratio} × {@value #CAP_MB_PER_RATIO} MB (8 GB at the default ratio). Real
 * recordings compress 2 to 10 times; a small file made to expand to gigabytes (a 198 KB file
 * once held 2.98 million envelopes) is refused beyond the limit, chunk by chunk in file
 * order, and the reader says how much. A user who trusts a file raises the ratio
 * ({@code --max-expansion}).
 */
public record ExpansionLimit(int ratio) {

    public static final int DEFAULT_RATIO = 32;
    public static final ExpansionLimit DEFAULT = new ExpansionLimit(DEFAULT_RATIO);
    static final int FLOOR_MB = 16;
    static final int CAP_MB_PER_RATIO = 256;

    public ExpansionLimit {
        if (ratio < 1) {
            throw new IllegalArgumentException("the expansion ratio is at least 1, not " + ratio);
        }
    }

    /** The bytes the chunks of a file of {@code fileSize} bytes may hold in all, the file's own size included. */
    long allowedBytes(long fileSize) {
        long cap = (long) ratio * CAP_MB_PER_RATIO << 20;
        long proportional = fileSize > cap / ratio ? cap : fileSize * ratio;
        return fileSize + Math.max((long) FLOOR_MB << 20, proportional);
    }

    /** The limit in words, for the note that says what was refused. */
    String describe(long fileSize) {
        return "a file of " + size(fileSize) + " may expand to " + size(allowedBytes(fileSize)) + " (" + ratio
                + " times its size more, at least " + FLOOR_MB + " MB, at most " + size((long) ratio * CAP_MB_PER_RATIO << 20)
                + "; --max-expansion raises the ratio)";
    }

    static String size(long bytes) {
        if (bytes >= 1L << 30) {
            return bytes % (1L << 30) == 0 ? (bytes >> 30) + " GB" : String.format(java.util.Locale.ROOT, "%.1f GB",
                    bytes / (double) (1L << 30));
        }
        if (bytes >= 10L << 20) {
            return (bytes >> 20) + " MB";
        }
        return bytes >= 10L << 10 ? (bytes >> 10) + " KB" : bytes + " bytes";
    }
}
