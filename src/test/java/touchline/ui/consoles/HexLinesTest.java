package touchline.ui.consoles;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class HexLinesTest {

    @Test
    void sixteenBytesALineWithTheirAsciiBeside() {
        byte[] b = new byte[20];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) (i < 16 ? 'A' + i : i == 16 ? 0 : 0x7f + i);
        }
        assertEquals("""
                0000  41 42 43 44 45 46 47 48  49 4a 4b 4c 4d 4e 4f 50  |ABCDEFGHIJKLMNOP|
                0010  00 90 91 92                                       |....|""",
                new HexLines().dump(b, 4096));
    }

    @Test
    void aCutDumpSaysHowMuchIsLeft() {
        assertEquals("0000  01 02                                             |..|\n… 3 more bytes",
                new HexLines().dump(new byte[]{1, 2, 3, 4, 5}, 2));
    }
}
