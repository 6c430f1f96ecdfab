package touchline.cli;

import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;
import touchline.record.ChunkCompression;

/**
 * Reads {@code --compression none|zstd|lz4} into a {@link ChunkCompression}: the names are
 * the MCAP spec's, with {@code none} for the empty string the spec uses for uncompressed.
 */
final class CompressionOption implements ITypeConverter<ChunkCompression> {

    @Override
    public ChunkCompression convert(String value) {
        String name = value.trim().toLowerCase(java.util.Locale.ROOT);
        return ChunkCompression.ofMcapName(name.equals("none") ? "" : name).orElseThrow(() ->
                new TypeConversionException("'" + value + "' is not a chunk compression (none, zstd or lz4)"));
    }
}
