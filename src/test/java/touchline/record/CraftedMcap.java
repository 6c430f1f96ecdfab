package touchline.record;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import java.util.zip.CRC32;

/**
 * Small MCAP files that claim or expand to far more than they are, built record by record:
 * one channel, then chunks of the same message repeated (which zstd packs a thousandfold),
 * no summary (the reader scans them). The reproducers of the reader's limits.
 */
final class CraftedMcap {

    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    /** Magic, a header, and channel 1 as {@code channel} describes it (with {@code schema} as schema 1, if any). */
    CraftedMcap(McapReader.ChannelInfo channel, McapReader.Schema schema) {
        out.writeBytes(McapRecords.MAGIC);
        out.writeBytes(McapSurgery.record(McapRecords.HEADER, McapSurgery.le(text(""), text("crafted"))));
        if (schema != null) {
            out.writeBytes(McapSurgery.record(McapRecords.SCHEMA, McapSurgery.le((short) 1, text(schema.name()),
                    text(schema.encoding()), schema.data().length, schema.data())));
        }
        ByteArrayOutputStream map = new ByteArrayOutputStream();
        channel.metadata().forEach((k, v) -> map.writeBytes(McapSurgery.le(text(k), text(v))));
        out.writeBytes(McapSurgery.record(McapRecords.CHANNEL, McapSurgery.le((short) 1,
                (short) (schema == null ? 0 : 1), text(channel.topic()), text(channel.messageEncoding()),
                map.size(), map.toByteArray())));
    }

    /** A file whose channel 1 is JSON text: every message plays as an envelope of another tool's channel. */
    static CraftedMcap json() {
        return new CraftedMcap(new McapReader.ChannelInfo(1, 0, "/flood", "json", Map.of()), null);
    }

    /** {@code count} messages of {@code data} on channel 1 at {@code logTime}: a chunk's records. */
    static byte[] messages(int count, byte[] data, long logTime) {
        byte[] one = McapSurgery.record(McapRecords.MESSAGE, McapSurgery.le((short) 1, 0, logTime, logTime, data));
        ByteArrayOutputStream records = new ByteArrayOutputStream(count * one.length);
        for (int i = 0; i < count; i++) {
            records.writeBytes(one);
        }
        return records.toByteArray();
    }

    /**
     * A chunk of {@code records} (their messages at {@code logTime}) compressed with
     * {@code compression}, claiming {@code claimed} bytes uncompressed.
     */
    CraftedMcap chunk(ChunkCompression compression, byte[] records, long logTime, long claimed) {
        byte[] stored = compression.compress(records, records.length);
        CRC32 crc = new CRC32();
        crc.update(records);
        out.writeBytes(McapSurgery.record(McapRecords.CHUNK, McapSurgery.le(logTime, logTime, claimed,
                (int) crc.getValue(), text(compression.mcapName()), (long) stored.length, stored)));
        return this;
    }

    /** A chunk of {@code records} (their messages at {@code logTime}) compressed with {@code compression}, claiming their true size. */
    CraftedMcap chunk(ChunkCompression compression, byte[] records, long logTime) {
        return chunk(compression, records, logTime, records.length);
    }

    /** A record of a private opcode (readers skip it): makes the file {@code bytes} larger. */
    CraftedMcap padding(int bytes) {
        out.writeBytes(McapSurgery.record(0x80, new byte[bytes]));
        return this;
    }

    /** The file: what was added, the data end and a footer without a summary. */
    byte[] bytes() {
        return McapSurgery.concat(out.toByteArray(), McapSurgery.record(McapRecords.DATA_END, McapSurgery.le(0)),
                McapSurgery.footer(0));
    }

    private static byte[] text(String s) {
        byte[] b = s.getBytes(StandardCharsets.UTF_8);
        return McapSurgery.le(b.length, b);
    }
}
