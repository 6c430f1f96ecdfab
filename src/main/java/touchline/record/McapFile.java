package touchline.record;

import java.io.Closeable;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/** The recording file a {@link McapReader} reads: positioned reads that fail at an early end. */
final class McapFile implements Closeable {

    private final FileChannel in;
    private final long size;

    McapFile(Path file) throws IOException {
        this.in = FileChannel.open(file, StandardOpenOption.READ);
        this.size = in.size();
    }

    long size() {
        return size;
    }

    /** The {@code n} bytes at {@code pos}. */
    byte[] read(long pos, int n) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(n);
        readFully(b, pos);
        return b.array();
    }

    /** Fills {@code b} from {@code pos} on. */
    void readFully(ByteBuffer b, long pos) throws IOException {
        while (b.hasRemaining()) {
            int r = in.read(b, pos + b.position());
            if (r < 0) {
                throw new IOException("unexpected end of file at byte " + (pos + b.position()));
            }
        }
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
