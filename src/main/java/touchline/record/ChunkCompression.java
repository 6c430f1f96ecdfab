package touchline.record;

import com.github.luben.zstd.Zstd;
import com.github.luben.zstd.ZstdInputStream;
import net.jpountz.lz4.LZ4FrameOutputStream;
import org.apache.commons.compress.compressors.lz4.FramedLZ4CompressorInputStream;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Arrays;
import java.util.Optional;

/**
 * The compressions the MCAP spec names for chunk records: none ({@code ""}), {@code zstd}
 * (a Zstandard frame) and {@code lz4} (an LZ4 frame). The writer compresses a whole chunk's
 * records at once; the reader decompresses into exactly the uncompressed size the chunk
 * declares, so a frame that yields anything else is refused, never trusted, and a claim is
 * never allocated before the frame has yielded it.
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
     * {@link IOException} with a user-facing reason for a damaged frame or a wrong size. The
     * output grows in steps with what the frame really yields (at most twice that), so a chunk
     * that claims far more than its frame holds costs what the frame holds, not the claim.
     */
    byte[] decompress(byte[] compressed, int uncompressedSize) throws IOException {
        if (this == NONE) {
            return compressed;
        }
        byte[] out = new byte[Math.min(uncompressedSize, FIRST_STEP)];
        int n = 0;
        boolean more;
        try (InputStream in = frame(compressed)) {
            while (n < uncompressedSize) {
                if (n == out.length) {
                    out = Arrays.copyOf(out, (int) Math.min(uncompressedSize, 2L * out.length));
                }
                int r = in.read(out, n, out.length - n);
                if (r < 0) {
                    break;
                }
                n += r;
            }
            more = in.read() != -1;
        } catch (IOException | RuntimeException e) {
            throw new IOException("its " + mcapName + " frame does not decompress (" + e.getMessage() + ")");
        }
        if (n != uncompressedSize || more) {
            throw new IOException("its " + mcapName + " frame holds " + (more ? "more than " + n : n)
                    + " bytes, the chunk says " + uncompressedSize);
        }
        return out;
    }

    // what a decompression allocates before the frame has shown it holds more
    private static final int FIRST_STEP = 1 << 20;

    /**
     * The decompressing stream of a frame. LZ4: Commons Compress reads every frame the format
     * allows (linked blocks, content size, block and content checksums); lz4-java's frame reader
     * refuses linked blocks, which the Python {@code mcap} writer uses for chunks over one block.
     */
    private InputStream frame(byte[] compressed) throws IOException {
        ByteArrayInputStream bytes = new ByteArrayInputStream(compressed);
        return switch (this) {
            case ZSTD -> new ZstdInputStream(bytes);
            case LZ4 -> new FramedLZ4CompressorInputStream(bytes);
            case NONE -> bytes;
        };
    }
}
