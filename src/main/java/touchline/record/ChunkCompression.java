package touchline.record;

import com.github.luben.zstd.Zstd;
import com.github.luben.zstd.ZstdException;
import net.jpountz.lz4.LZ4Exception;
import net.jpountz.lz4.LZ4FrameInputStream;
import net.jpountz.lz4.LZ4FrameOutputStream;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.Arrays;
import java.util.Optional;

/**
 * The compressions the MCAP spec names for chunk records: none ({@code ""}), {@code zstd}
 * (a Zstandard frame) and {@code lz4} (an LZ4 frame). The writer compresses a whole chunk's
 * records at once; the reader decompresses into exactly the uncompressed size the chunk
 * declares, so a frame that claims or yields anything else is refused, never trusted.
 */
public enum ChunkCompression {
    NONE(""),
    ZSTD("zstd"),
    LZ4("lz4");

    // Fast levels: the chunk is compressed on the thread that publishes envelopes
    private static final int ZSTD_LEVEL = 1;

    private final String mcapName;

    ChunkCompression(String mcapName) {
        this.mcapName = mcapName;
    }

    /** The chunk record's {@code compression} field. */
    public String mcapName() {
        return mcapName;
    }

    /** The compression a chunk record names, or empty for one this reader does not know. */
    public static Optional<ChunkCompression> ofMcapName(String name) {
        return Arrays.stream(values()).filter(c -> c.mcapName.equals(name)).findFirst();
    }

    /** {@code data[0, length)} compressed; the array itself for {@link #NONE}. */
    byte[] compress(byte[] data, int length) {
        return switch (this) {
            case NONE -> data;
            case ZSTD -> {
                byte[] out = new byte[(int) Zstd.compressBound(length)];
                long n = Zstd.compressByteArray(out, 0, out.length, data, 0, length, ZSTD_LEVEL);
                yield Arrays.copyOf(out, (int) n);
            }
            case LZ4 -> {
                ByteArrayOutputStream out = new ByteArrayOutputStream(length / 2 + 64);
                // 256 KiB blocks, no content checksum: the default 4 MiB block buffer was allocated
                // anew for every chunk, and the chunk record carries its own CRC
                try (LZ4FrameOutputStream lz4 = new LZ4FrameOutputStream(out, LZ4FrameOutputStream.BLOCKSIZE.SIZE_256KB,
                        LZ4FrameOutputStream.FLG.Bits.BLOCK_INDEPENDENCE)) {
                    lz4.write(data, 0, length);
                } catch (IOException e) {
                    throw new UncheckedIOException(e); // a memory stream does not fail
                }
                yield out.toByteArray();
            }
        };
    }

    /**
     * Decompresses {@code compressed} into exactly {@code uncompressedSize} bytes. Throws
     * {@link IOException} with a user-facing reason for a damaged frame or a wrong size.
     */
    byte[] decompress(byte[] compressed, int uncompressedSize) throws IOException {
        switch (this) {
            case NONE -> {
                return compressed;
            }
            case ZSTD -> {
                byte[] out = new byte[uncompressedSize];
                long n;
                try {
                    n = Zstd.decompressByteArray(out, 0, uncompressedSize, compressed, 0, compressed.length);
                } catch (ZstdException e) {
                    throw new IOException("its zstd frame does not decompress (" + e.getMessage() + ")");
                }
                if (n != uncompressedSize) {
                    throw new IOException("its zstd frame holds " + n + " bytes, the chunk says " + uncompressedSize);
                }
                return out;
            }
            case LZ4 -> {
                byte[] out = new byte[uncompressedSize];
                int n;
                boolean more;
                try (LZ4FrameInputStream in = new LZ4FrameInputStream(new ByteArrayInputStream(compressed))) {
                    n = in.readNBytes(out, 0, uncompressedSize);
                    more = in.read() != -1;
                } catch (IOException | LZ4Exception | IllegalArgumentException e) {
                    throw new IOException("its lz4 frame does not decompress (" + e.getMessage() + ")");
                }
                if (n != uncompressedSize || more) {
                    throw new IOException("its lz4 frame does not hold the " + uncompressedSize
                            + " bytes the chunk says");
                }
                return out;
            }
            default -> throw new IllegalStateException();
        }
    }
}
