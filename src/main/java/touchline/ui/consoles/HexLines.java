package touchline.ui.consoles;

/**
 * A datagram as the network console shows it: 16 bytes a line, offset, hex, and the printable
 * ASCII beside it ({@code .} for the rest), the way hexdump -C shows bytes.
 */
final class HexLines {

    private static final char[] DIGITS = "0123456789abcdef".toCharArray();

    String dump(byte[] bytes, int max) {
        int n = Math.min(bytes.length, max);
        StringBuilder out = new StringBuilder(n * 4 + 16);
        for (int line = 0; line < n; line += 16) {
            if (line > 0) {
                out.append('\n');
            }
            out.append(String.format("%04x  ", line));
            StringBuilder ascii = new StringBuilder(16);
            for (int i = line; i < line + 16; i++) {
                if (i < n) {
                    out.append(DIGITS[(bytes[i] >> 4) & 0xF]).append(DIGITS[bytes[i] & 0xF]).append(' ');
                    int b = bytes[i] & 0xFF;
                    ascii.append(b >= 0x20 && b < 0x7F ? (char) b : '.');
                } else {
                    out.append("   ");
                }
                if (i == line + 7) {
                    out.append(' ');
                }
            }
            out.append(" |").append(ascii).append('|');
        }
        if (bytes.length > n) {
            out.append("\n… ").append(bytes.length - n).append(" more bytes");
        }
        return out.toString();
    }
}
