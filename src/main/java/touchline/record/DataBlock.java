package touchline.record;

/**
 * A chunk (or, for {@code loose}, a single message record outside any chunk) of a recording, in
 * file order; {@code chunk} is its header once the file is open (null for a loose message).
 */
record DataBlock(long offset, long length, long startTime, long endTime, boolean loose, ChunkHeader chunk) {

    DataBlock(long offset, long length, long startTime, long endTime, boolean loose) {
        this(offset, length, startTime, endTime, loose, null);
    }
}
