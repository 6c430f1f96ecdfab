package touchline.record;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.zip.CRC32;

/**
 * What a chunk record's header says: the size its records claim uncompressed, their CRC
 * and compression, and where the stored records lie in the file ({@code cut} when they
 * run past its end or the chunk's length).
 */
record ChunkHeader(long uncompressedSize, long crc, ChunkCompression compression, long recordsStart,
                   long storedLength, boolean cut) {

    /** Start, end, uncompressed size, CRC, compression string length, records length. */
    static final int FIXED_BYTES = 8 + 8 + 8 + 4 + 4 + 8;

    /** The bytes reading the chunk yields: what decompressing it claims, or what is stored. */
    long yields() {
        return compression == ChunkCompression.NONE ? storedLength : uncompressedSize;
    }

    /**
     * The chunk's records, decompressed and checked against its CRC and size, or null (said in
     * {@code problems}) when they are damaged; {@code offset} is the chunk's, for the message.
     */
    ByteBuffer records(McapFile file, long offset, CopyOnWriteArrayList<String> problems) throws IOException {
        byte[] stored = file.read(recordsStart, (int) storedLength);
        ByteBuffer records;
        try {
            records = ByteBuffer.wrap(compression.decompress(stored, (int) uncompressedSize));
        } catch (IOException e) {
            problems.addIfAbsent("chunk at byte " + offset + " is damaged: " + e.getMessage()
                    + "; its messages are skipped, the rest plays");
            return null;
        }
        records.order(ByteOrder.LITTLE_ENDIAN);
        if (!cut && (crc != 0 || uncompressedSize != records.remaining())) {
            CRC32 check = new CRC32();
            check.update(records.duplicate());
            if ((crc != 0 && check.getValue() != crc) || uncompressedSize != records.remaining()) {
                problems.addIfAbsent("chunk at byte " + offset + " is corrupt (CRC "
                        + Long.toHexString(check.getValue()) + ", expected " + Long.toHexString(crc) + ", "
                        + records.remaining() + " of " + uncompressedSize + " bytes); its messages are"
                        + " skipped, the rest plays");
                return null;
            }
        }
        return records;
    }
}
