package touchline.record;

import touchline.record.McapRecords.Bytes;

import java.util.Arrays;
import java.util.Map;
import java.util.TreeMap;

/**
 * The message indexes of the chunk a {@link McapWriter} is filling: per channel, the (log time,
 * offset in the chunk) of each message, written after the chunk as one MESSAGE_INDEX record per
 * channel in channel order, each sorted by time. Arrays grow with the channels and are reused
 * chunk after chunk: this runs once per recorded message.
 */
final class MessageIndexes {

    private long[][] entries = new long[16][];
    private int[] sizes = new int[16];
    private int[] channels = new int[16];
    private int channelCount;

    /** Makes room for channel ids below {@code channels}. */
    void ensureChannels(int count) {
        if (count > sizes.length) {
            int n = Math.max(count, sizes.length * 2);
            entries = Arrays.copyOf(entries, n);
            sizes = Arrays.copyOf(sizes, n);
            channels = Arrays.copyOf(channels, n);
        }
    }

    /** Notes a message of {@code channelId} at {@code time}, {@code offset} bytes into the chunk. */
    void add(int channelId, long time, long offset) {
        long[] index = entries[channelId];
        int n = sizes[channelId];
        if (n == 0) {
            channels[channelCount++] = channelId;
            if (index == null) {
                index = new long[64];
                entries[channelId] = index;
            }
        } else if (n + 2 > index.length) {
            index = Arrays.copyOf(index, index.length * 2);
            entries[channelId] = index;
        }
        index[n] = time;
        index[n + 1] = offset;
        sizes[channelId] = n + 2;
    }

    /**
     * Writes the chunk's message index records into {@code out}, which will lie at file offset
     * {@code start}, and empties the indexes for the next chunk; returns each channel's record offset.
     */
    Map<Integer, Long> writeAndClear(Bytes out, long start) {
        Map<Integer, Long> offsets = new TreeMap<>();
        Arrays.sort(channels, 0, channelCount);
        for (int c = 0; c < channelCount; c++) {
            int channel = channels[c];
            int n = sizes[channel];
            long[] index = entries[channel];
            sortByTime(index, n);
            offsets.put(channel, start + out.size);
            int rec = out.beginRecord(McapRecords.MESSAGE_INDEX);
            out.u16(channel);
            out.u32(n * 8L);
            for (int i = 0; i < n; i++) {
                out.u64(index[i]);
            }
            out.endRecord(rec);
            sizes[channel] = 0;
        }
        channelCount = 0;
        return offsets;
    }

    /**
     * Sorts the (log time, offset) pairs {@code index[0, n)} by time, then offset: readers
     * binary-search message indexes, and envelopes of several threads can reach the writer
     * slightly out of order. Already sorted is the common case and costs one pass.
     */
    private static void sortByTime(long[] index, int n) {
        boolean sorted = true;
        for (int i = 2; i < n && sorted; i += 2) {
            sorted = index[i - 2] <= index[i];
        }
        if (sorted) {
            return;
        }
        long[][] pairs = new long[n / 2][];
        for (int i = 0; i < n; i += 2) {
            pairs[i / 2] = new long[]{index[i], index[i + 1]};
        }
        Arrays.sort(pairs, (a, b) -> a[0] != b[0] ? Long.compare(a[0], b[0]) : Long.compare(a[1], b[1]));
        for (int i = 0; i < pairs.length; i++) {
            index[2 * i] = pairs[i][0];
            index[2 * i + 1] = pairs[i][1];
        }
    }
}
