package touchline.record;

import org.junit.jupiter.api.Test;
import touchline.record.McapRecords.Bytes;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

class MessageIndexesTest {

    /** Channels beyond the first arrays (16), messages out of time order, two chunks in a row. */
    @Test
    void writesOneSortedIndexPerChannelInChannelOrderAndStartsAfreshForTheNextChunk() {
        MessageIndexes indexes = new MessageIndexes();
        indexes.ensureChannels(40);
        indexes.add(39, 300, 0);
        indexes.add(3, 200, 50);
        indexes.add(39, 100, 100);
        indexes.add(39, 100, 90);
        Bytes out = new Bytes(16);
        out.u8(0); // the records land after one byte already in the buffer
        Map<Integer, Long> offsets = indexes.writeAndClear(out, 1000);

        ByteBuffer b = ByteBuffer.wrap(out.buf, 1, out.size - 1).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(List.of(3, 39), List.copyOf(offsets.keySet()));
        assertEquals(1001L, offsets.get(3));
        assertEquals(List.of(200L, 50L), record(b, 3));
        assertEquals(1001L + 9 + 2 + 4 + 16, offsets.get(39));
        assertEquals(List.of(100L, 90L, 100L, 100L, 300L, 0L), record(b, 39));
        assertEquals(0, b.remaining());

        indexes.add(5, 7, 8);
        Bytes next = new Bytes(16);
        assertEquals(Map.of(5, 0L), indexes.writeAndClear(next, 0));
        assertEquals(List.of(7L, 8L), record(ByteBuffer.wrap(next.buf, 0, next.size).order(ByteOrder.LITTLE_ENDIAN), 5));
    }

    private static List<Long> record(ByteBuffer b, int channel) {
        assertEquals(McapRecords.MESSAGE_INDEX, b.get() & 0xFF);
        long length = b.getLong();
        assertEquals(channel, b.getShort() & 0xFFFF);
        int n = b.getInt();
        assertEquals(length, 2 + 4 + n);
        List<Long> entries = new ArrayList<>();
        for (int i = 0; i < n / 8; i++) {
            entries.add(b.getLong());
        }
        return entries;
    }
}
